// The `firn` command line (DESIGN.md section 5): thin, it parses arguments and calls the engine.
#include <CLI/CLI.hpp>

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <thread>

#include "apps/commands.hpp"
#include "engine/openmp_wait.hpp"
#include "engine/version.hpp"

namespace {

// The threads `--threads` asks for in argv, or `cpus` (the default: all of them).
int requested_threads(char** argv, int cpus) {
  for (int i = 1; argv[i]; ++i) {
    const std::string a = argv[i];
    if (a == "--threads" && argv[i + 1]) return std::max(1, std::atoi(argv[i + 1]));
    if (a.rfind("--threads=", 0) == 0) return std::max(1, std::atoi(a.c_str() + 10));
  }
  return cpus;
}

// The tasks other than this one that were runnable at each of ten readings of /proc/loadavg, 1 ms
// apart (the shell that started firn may still be runnable at the first), or -1 if unreadable.
int others_runnable() {
  int fewest = -1;
  for (int i = 0; i < 10; ++i) {
    if (i > 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    std::ifstream in("/proc/loadavg");
    std::string text;
    std::getline(in, text);
    const int runnable = firn::runnable_tasks(text);  // this process among them
    if (runnable < 1) return -1;
    fewest = fewest < 0 ? runnable - 1 : std::min(fewest, runnable - 1);
  }
  return fewest;
}

// Chooses how idle OpenMP threads wait (engine/openmp_wait.hpp) unless the user did. libgomp reads
// the variables as it loads, before main, so firn sets one and restarts itself once, naming it in
// FIRN_OPENMP_WAIT; the restarted firn records the choice and removes both, so that the processes
// it starts (a sweep's runs, sbatch's jobs) choose for themselves.
void choose_openmp_waiting(char** argv) {
  if (const char* variable = std::getenv("FIRN_OPENMP_WAIT")) {
    firn::record_openmp_wait(firn::openmp_wait());
    unsetenv(std::string(variable).c_str());
    unsetenv("FIRN_OPENMP_WAIT");
    return;
  }
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  cpu_set_t set;
  const int cpus = sched_getaffinity(0, sizeof(set), &set) == 0 ? CPU_COUNT(&set) : 1;
  const bool spin = firn::spin_while_waiting(others_runnable(), cpus, requested_threads(argv, cpus));
  const char* variable = spin ? "GOMP_SPINCOUNT" : "OMP_WAIT_POLICY";
  setenv(variable, spin ? std::to_string(firn::kOpenMPSpinCount).c_str() : "passive", 1);
  setenv("FIRN_OPENMP_WAIT", variable, 1);
  execv("/proc/self/exe", argv);  // returns only if it failed: then carry on as libgomp has it
  unsetenv(variable);
  unsetenv("FIRN_OPENMP_WAIT");
}

}  // namespace

int main(int argc, char** argv) {
  choose_openmp_waiting(argv);
  CLI::App app{"firn: a Material Point Method engine for snow, rubber tires and rigid bodies"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("firn ") + firn::firn_version());
  firn::app::add_bench_command(app);
  firn::app::add_verify_command(app);
  firn::app::add_run_command(app);
  firn::app::add_render_command(app);
  firn::app::add_check_command(app);
  firn::app::add_sweep_command(app);
  firn::app::add_report_command(app);
  firn::app::add_study_command(app);
  firn::app::add_help_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);  // prints help, the version or the error
    return status == 0 ? 0 : 2;       // every command-line mistake is bad input (commands.hpp)
  }
  return firn::app::exit_status();
}
