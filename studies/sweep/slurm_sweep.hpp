// A sweep submitted to Slurm (firn sweep --scheduler slurm): OUT/slurm/sweep.sbatch, a job array of
// one task per run (slurm_job.hpp), submitted with sbatch; `firn sweep --collect OUT`
// (sweep_collect.hpp) later gathers the finished runs.
#pragma once

#include "studies/sweep/sweep_plan.hpp"

namespace firn::sweep {

// Writes the job array and submits it, reporting the job's id or why sbatch failed; returns the
// exit status (0 submitted, 1 sbatch failed).
int submit_slurm_sweep(const SweepOptions& o, const SweepPlan& plan, const SweepReport& report);

}  // namespace firn::sweep
