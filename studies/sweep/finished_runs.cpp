#include "studies/sweep/finished_runs.hpp"

#include <filesystem>
#include <string>

#include "engine/output/atomic_file.hpp"
#include "engine/output/png_file.hpp"
#include "studies/sweep/footprint_comparison.hpp"
#include "studies/sweep/gnuplot.hpp"
#include "studies/sweep/metric_plot.hpp"
#include "studies/sweep/sweep_table.hpp"

namespace firn::sweep {

bool FinishedRuns::all_ok() const {
  for (const auto& [index, record] : finished_)
    if (record.status != "ok") return false;
  return true;
}

void FinishedRuns::write() const {
  std::vector<std::string> keys;
  for (const VariedKey& k : plan_.keys) keys.push_back(k.key);
  write_file_atomically(plan_.out + "/sweep.csv", sweep_csv(keys, in_run_order(), plan_.at_times));
}

void FinishedRuns::plot() const {
  const std::string dir = plan_.out + "/plots";
  const std::vector<RunRecord> runs = in_run_order();
  for (const std::string& metric : plan_.plots) {
    const auto plot = metric_plot(metric, plan_.keys, runs);
    if (!plot) {
      if (plan_.plots_named) report_("--plot " + metric + ": no finished run wrote it");
      continue;
    }
    if (draw_plot_or_warn("firn sweep", dir, metric, *plot) == PlotStatus::no_gnuplot) break;
  }
  std::vector<FootprintPanel> footprints;
  for (const auto& [index, record] : finished_)
    if (auto panel = last_footprint(run_dir(plan_, index))) {
      for (std::size_t k = 0; k < plan_.keys.size(); ++k)
        panel->label += (k ? ", " : "") + plan_.keys[k].key + "=" + record.values[k];
      footprints.push_back(std::move(*panel));
    }
  if (footprints.empty()) return;
  std::filesystem::create_directories(dir);
  write_png(dir + "/footprints.png", footprint_comparison(footprints));
}

std::vector<RunRecord> FinishedRuns::in_run_order() const {
  std::vector<RunRecord> records;
  for (const auto& [index, record] : finished_) records.push_back(record);
  return records;
}

}  // namespace firn::sweep
