// A sweep's plan (firn sweep): the options that define its runs, kept in OUT/sweep.args so that
// `firn sweep --collect` can rebuild them, and what they come to: the varied keys, every
// combination of their values (each validated by loading its scene), the times and metrics of
// sweep.csv and the plots, and each run's folder and `firn run` command line.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "studies/sweep/value_list.hpp"

namespace firn::sweep {

struct SweepOptions {
  std::string scene;           // a scene file, or the name of a shipped scene
  std::string shipped_scenes;  // where a scene given by name is looked for (engine/scene/scene_lookup.hpp)
  std::string out;             // empty: out/<scene name>_sweep
  std::string at, plot;        // comma-separated: times for the C@T columns, metrics to plot
  std::string backend = "openmp";
  std::string checkpoint_every;           // each run's --checkpoint-every (a time); empty: none
  std::string render = "none";            // each run's --render: none, spheres or surface
  std::vector<std::string> varies, sets;  // "KEY=V1,V2,..." and "KEY=VALUE"
  std::vector<std::string> sbatch;        // options for a Slurm job array
  int jobs = 1;                           // runs at a time (local scheduler)
  bool preview = false;
  bool resume = false;  // skip the finished runs, resume the interrupted ones from their checkpoints
};

struct SweepPlan {
  std::vector<VariedKey> keys;
  std::vector<std::vector<std::string>> combinations;
  std::vector<double> at_times;
  std::vector<std::string> plots;  // metric columns; a named one that no run writes is reported
  bool plots_named = false;
  std::string scene;  // the scene file, as an absolute path: the runs may start elsewhere
  std::string out;
};

// Where a sweep's progress and warnings go, one line at a time (firn sweep prints them).
using SweepReport = std::function<void(const std::string& line)>;

// Reads the options and loads every combination's scene; throws std::invalid_argument (bad
// options) or SceneError (a bad scene or value) before anything is written.
SweepPlan make_plan(const SweepOptions& o);

// Creates the output folder and writes OUT/sweep.args: the options that define the runs.
void save_sweep_args(const SweepOptions& o, const SweepPlan& plan);

// The options OUT/sweep.args holds (out = `dir`); throws std::invalid_argument when there is none.
SweepOptions read_sweep_args(const std::string& dir);

// Run `index`'s output folder.
std::string run_dir(const SweepPlan& plan, std::size_t index);

// The `firn run` command line of run `index`, without --threads; `self` is firn's path.
std::vector<std::string> run_command(const SweepOptions& o, const SweepPlan& plan, std::size_t index,
                                     const std::string& self);

// What a resumed sweep does with run `index` (firn sweep --resume): nothing when it finished (its
// summary.json says ok or unstable, both final), `firn run --resume` when it has a checkpoint,
// else it runs from the start.
enum class RunState { finished, resumable, to_run };
RunState run_state(const SweepPlan& plan, std::size_t index);

// The `firn run --resume` command line of run `index`, without --threads.
std::vector<std::string> resume_command(const SweepOptions& o, const SweepPlan& plan, std::size_t index,
                                        const std::string& self);

}  // namespace firn::sweep
