// Starting a program as a child process from an argument vector (fork and exec, never a shell),
// with its standard output and error in a log file and standard input from /dev/null.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace firn::sweep {

struct ChildSpec {
  std::vector<std::string> argv;  // argv[0] is the program
  std::string log_path;           // created or truncated (appended to with append_log); receives stdout and stderr
  std::string work_dir;           // the child's working directory; empty: this process's
  bool search_path = false;       // look argv[0] up in PATH (execvp) rather than use it as a path (execv)
  bool append_log = false;
};

// Starts the child with the default signal dispositions and an empty signal mask, whatever this
// process has blocked. A child whose exec fails writes why to its log and exits with status 127.
// Throws std::runtime_error when the log cannot be opened or fork fails.
pid_t start_child(const ChildSpec& spec);

// Waits for the child and returns its exit status, or 128 + the signal that ended it.
int wait_child(pid_t pid);

// The status waitpid reported, as an exit status (128 + signal for a child ended by a signal).
int exit_status_of(int wait_status);

// The path of the running executable (/proc/self/exe resolved), so that firn can start itself.
std::string self_executable();

}  // namespace firn::sweep
