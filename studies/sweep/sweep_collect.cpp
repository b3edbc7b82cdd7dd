#include "studies/sweep/sweep_collect.hpp"

#include <filesystem>
#include <utility>

#include "studies/sweep/finished_runs.hpp"
#include "studies/sweep/run_record.hpp"

namespace firn::sweep {

SweepPlan saved_plan(const std::string& dir, const std::string& plot, const std::string& shipped_scenes) {
  SweepOptions o = read_sweep_args(dir);
  o.shipped_scenes = shipped_scenes;
  if (!plot.empty()) o.plot = plot;
  return make_plan(o);
}

CollectedSweep collect_sweep(const std::string& dir, const std::string& plot, const std::string& shipped_scenes,
                             const SweepReport& report) {
  return collect_sweep(saved_plan(dir, plot, shipped_scenes), report);
}

CollectedSweep collect_sweep(const SweepPlan& plan, const SweepReport& report) {
  FinishedRuns finished(plan, report);
  CollectedSweep c;
  for (std::size_t i = 0; i < plan.combinations.size(); ++i) {
    if (!std::filesystem::exists(run_dir(plan, i) + "/summary.json")) {
      c.missing += (c.missing.empty() ? "" : ", ") + std::to_string(i + 1);
      continue;
    }
    RunRecord record;
    record.values = plan.combinations[i];
    read_run_outputs(run_dir(plan, i), record);
    finished.add(i, std::move(record));
  }
  finished.write();
  finished.plot();
  c.finished = finished.size();
  c.total = plan.combinations.size();
  c.all_ok = finished.all_ok();
  return c;
}

}  // namespace firn::sweep
