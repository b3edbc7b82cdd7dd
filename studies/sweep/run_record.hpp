// What a sweep keeps of one finished run: its varied values, the summary.json fields sweep.csv
// reports, and its metrics history, read back from the run's output folder.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "studies/sweep/metrics_history.hpp"

namespace firn::sweep {

struct RunRecord {
  std::vector<std::string> values;  // one per varied key, as given
  std::string status = "failed";    // summary.json's status; "failed" when there is no summary
  std::optional<double> steps, particles, wall_seconds, particle_steps_per_second;
  std::optional<MetricsHistory> metrics;  // none when metrics.csv is missing or unreadable
};

// The value of a top-level key of a flat JSON object such as summary.json, as text (a string
// unquoted and unescaped); none when the key is absent or null.
std::optional<std::string> json_value(const std::string& json, const std::string& key);

// The whole file; none when it cannot be read.
std::optional<std::string> file_text(const std::string& path);

// Fills status, the counts and the metrics from DIR/summary.json and DIR/metrics.csv.
void read_run_outputs(const std::string& dir, RunRecord& record);

}  // namespace firn::sweep
