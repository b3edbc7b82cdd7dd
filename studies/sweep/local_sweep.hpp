// A sweep run here (firn sweep --scheduler local): every run of the plan as a child `firn run`,
// `jobs` at a time on cores / jobs threads each, each finished run's row written to sweep.csv as it
// ends, then the plots. SIGINT or SIGTERM stops the runs still going (each writes its checkpoint);
// they get no row. With SweepOptions::resume, the runs that finished keep their outputs and rows,
// and the others continue from their checkpoints or start again (sweep_plan.hpp, run_state).
#pragma once

#include "studies/sweep/sweep_plan.hpp"

namespace firn::sweep {

// Runs the plan, reporting a line when it starts, as each run ends, when it is interrupted and when
// it is done; returns the exit status: 0 every run ok, 1 some run not ok, 130 interrupted.
int run_local_sweep(const SweepOptions& o, const SweepPlan& plan, const SweepReport& report);

}  // namespace firn::sweep
