// firn sweep --collect DIR: sweep.csv and the plots of a sweep whose runs were started elsewhere
// (a Slurm job array), from the runs that have finished; the sweep's options are in DIR/sweep.args.
#pragma once

#include <cstddef>
#include <string>

#include "studies/sweep/sweep_plan.hpp"

namespace firn::sweep {

struct CollectedSweep {
  std::size_t finished = 0, total = 0;
  std::string missing;  // the numbers of the runs without a summary.json, e.g. "2, 5"; empty: none
  bool all_ok = false;  // every finished run's status is ok
};

// The plan of the sweep in DIR, from DIR/sweep.args; `plot`: the metrics to plot, or empty for the
// sweep's own. Throws std::invalid_argument (not a sweep's folder) or SceneError (its scene no
// longer loads).
SweepPlan saved_plan(const std::string& dir, const std::string& plot, const std::string& shipped_scenes);

// Writes the plan's sweep.csv and plots from its finished runs.
CollectedSweep collect_sweep(const SweepPlan& plan, const SweepReport& report);

// collect_sweep(saved_plan(dir, plot, shipped_scenes), report).
CollectedSweep collect_sweep(const std::string& dir, const std::string& plot, const std::string& shipped_scenes,
                             const SweepReport& report);

}  // namespace firn::sweep
