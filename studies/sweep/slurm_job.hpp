// A sweep as a Slurm job array (firn sweep --scheduler slurm): one array task per run, each task
// running its own command line with its output in its own log file.
#pragma once

#include <string>
#include <vector>

namespace firn::sweep {

struct SlurmTask {
  std::vector<std::string> argv;  // the run's command line, argv[0] an absolute path
  std::string log_path;           // the run's standard output and error
};

struct SlurmJob {
  std::string name;                         // #SBATCH --job-name
  std::string slurm_output;                 // Slurm's own output per task, %a for the task number
  std::vector<std::string> sbatch_options;  // more #SBATCH lines as given, e.g. "--partition=debug"
  std::vector<SlurmTask> tasks;             // task i + 1 of the array runs tasks[i]
};

// The batch script: #SBATCH lines with --array=1-N, then one case per task that runs its command
// line with `--threads` set to the CPUs Slurm gave the task (SLURM_CPUS_PER_TASK, else 1). Every
// word is quoted for the shell.
std::string slurm_array_script(const SlurmJob& job);

// The word quoted for a POSIX shell: 'it'\''s'.
std::string shell_quoted(const std::string& word);

}  // namespace firn::sweep
