// The runs of a sweep that have finished so far, in run order whatever order they finished in:
// written to OUT/sweep.csv (sweep_table.hpp) and plotted against time under OUT/plots/.
#pragma once

#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "studies/sweep/run_record.hpp"
#include "studies/sweep/sweep_plan.hpp"

namespace firn::sweep {

class FinishedRuns {
 public:
  FinishedRuns(const SweepPlan& plan, SweepReport report) : plan_(plan), report_(std::move(report)) {}

  void add(std::size_t index, RunRecord record) { finished_[index] = std::move(record); }
  std::size_t size() const { return finished_.size(); }
  bool all_ok() const;

  void write() const;  // OUT/sweep.csv
  // OUT/plots/METRIC.png for every plotted metric some run wrote, and OUT/plots/footprints.png
  // when the runs wrote footprints (footprint_comparison.hpp).
  void plot() const;

 private:
  std::vector<RunRecord> in_run_order() const;

  const SweepPlan& plan_;
  SweepReport report_;
  std::map<std::size_t, RunRecord> finished_;  // by run index
};

}  // namespace firn::sweep
