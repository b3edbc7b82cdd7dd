// sweep.csv (DESIGN.md section 5, issue 5 item 7): one row per finished run.
#pragma once

#include <string>
#include <vector>

#include "studies/sweep/run_record.hpp"

namespace firn::sweep {

// The text of sweep.csv. Columns: one per varied key (the key as header, the value as given),
// then status,steps,particles,wall_seconds,particle_steps_per_second, then for every scene-metric
// column C (the union over the runs' metrics.csv files, in first-seen order) mean_C (the mean over
// the frames after frame 0) and C@T for each time T of `at_times` (the value at the first frame
// with time >= T - 1e-9). A value a run does not have is empty; numbers are printed with %.6g.
std::string sweep_csv(const std::vector<std::string>& keys, const std::vector<RunRecord>& runs,
                      const std::vector<double>& at_times);

// The union of the runs' scene-metric columns, in first-seen order.
std::vector<std::string> scene_metric_columns(const std::vector<RunRecord>& runs);

}  // namespace firn::sweep
