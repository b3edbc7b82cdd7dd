// The randomised scenes run in bulk: each scene of stability_random_scene.hpp runs as a child
// `firn run SCENE --out DIR --threads 1` (started from an argument vector), `jobs` at a time, and
// is classified by its exit status, its log and its outputs:
//   finished    exit 0
//   guard_stop  exit 1 with the stability guard's message in the log
//   bad_input   exit 2: the generator wrote a scene firn refuses (a generator bug: a failure)
//   crash       any other exit, or a signal (a failure)
//   nan         a non-finite number in metrics.csv or a .vtp frame (a failure, whatever the exit)
// Folders of runs that did not fail are removed, so the study's output stays small; a failing
// run keeps its scene.toml, log.txt and outputs under DIR/NNNN/.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace firn::study {

struct RandomRunResult {
  int index = 0;
  std::string outcome;  // finished, guard_stop, bad_input, crash or nan
  int exit_status = 0;
  std::string detail;   // the guard's or firn's message, or where the NaN is
  double seconds = 0;
  long particles_estimate = 0;
  std::string scene;    // stability_random_scene.hpp's one-line summary
  bool failed() const { return outcome == "bad_input" || outcome == "crash" || outcome == "nan"; }
};

struct RandomRunSettings {
  std::string firn;  // the firn executable
  std::string dir;   // each scene under DIR/NNNN/
  std::uint64_t seed = 1;
  int count = 200;
  int jobs = 2;
  std::string backend = "openmp";  // each run's --backend
};

// Runs scenes 0 .. count-1 and reports each as it ends (in the order they end).
void run_random_scenes(const RandomRunSettings& settings, const std::function<void(const RandomRunResult&)>& on_result);

// The classification above, from a run's exit status, log text and non-finite outputs.
std::string classify_random_run(int exit_status, const std::string& log, bool non_finite);

}  // namespace firn::study
