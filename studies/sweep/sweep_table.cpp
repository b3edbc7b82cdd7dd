#include "studies/sweep/sweep_table.hpp"

#include <algorithm>
#include <optional>

#include "studies/sweep/csv.hpp"

namespace firn::sweep {
namespace {

std::string optional_number(const std::optional<double>& v) { return v ? csv_number(*v) : ""; }

}  // namespace

std::vector<std::string> scene_metric_columns(const std::vector<RunRecord>& runs) {
  std::vector<std::string> columns;
  for (const RunRecord& run : runs)
    if (run.metrics)
      for (const std::string& c : run.metrics->scene_columns())
        if (std::find(columns.begin(), columns.end(), c) == columns.end()) columns.push_back(c);
  return columns;
}

std::string sweep_csv(const std::vector<std::string>& keys, const std::vector<RunRecord>& runs,
                      const std::vector<double>& at_times) {
  const std::vector<std::string> metrics = scene_metric_columns(runs);
  std::vector<std::string> header = keys;
  for (const char* c : {"status", "steps", "particles", "wall_seconds", "particle_steps_per_second"})
    header.push_back(c);
  for (const std::string& c : metrics) {
    header.push_back("mean_" + c);
    for (const double t : at_times) header.push_back(c + "@" + csv_number(t));
  }
  std::string text;
  auto add_row = [&text](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) text += (i ? "," : "") + csv_field(cells[i]);
    text += "\n";
  };
  add_row(header);
  for (const RunRecord& run : runs) {
    std::vector<std::string> row = run.values;
    row.resize(keys.size());
    row.push_back(run.status);
    for (const auto& v : {run.steps, run.particles, run.wall_seconds, run.particle_steps_per_second})
      row.push_back(optional_number(v));
    for (const std::string& c : metrics) {
      row.push_back(run.metrics ? optional_number(run.metrics->mean_after_first_frame(c)) : "");
      for (const double t : at_times) row.push_back(run.metrics ? optional_number(run.metrics->value_at(c, t)) : "");
    }
    add_row(row);
  }
  return text;
}

}  // namespace firn::sweep
