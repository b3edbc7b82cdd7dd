// The stability study's results: stability.csv, one row per measurement, rewritten (atomically)
// after every row so that nothing is lost if the study stops, and stability.md, the summary table.
//
// stability.csv columns:
//   check    cfl, impact_speed, incompressibility, long_run or random_scene
//   subject  what was tested (a material, a scene, a random scene's number)
//   setting  the parameter of this row, e.g. "cfl=0.8", "nu=0.499", "largest stable cfl"
//   value    the measured number (empty when there is none)
//   unit     its unit ("" for a dimensionless number)
//   outcome  finished, guard_stop, nan, energy_blow_up, crash, bad_input (one run), or result (a
//            figure derived from several runs, e.g. the bisection's answer)
//   detail   the guard's message, the bracket and tolerance, what was measured, ...
//   seconds  wall time of the run(s) behind the row
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace firn::study {

struct StabilityRow {
  std::string check, subject, setting;
  std::optional<double> value;
  std::string unit, outcome, detail;
  double seconds = 0;
  bool headline = false;  // also a line of the summary table in stability.md
};

class StabilityReport {
 public:
  explicit StabilityReport(std::string dir) : dir_(std::move(dir)) {}
  // Appends the row and rewrites DIR/stability.csv.
  void add(const StabilityRow& row);
  const std::vector<StabilityRow>& rows() const { return rows_; }
  std::string csv() const;
  // The markdown summary: a table of the headline rows, then `notes` (markdown) verbatim.
  std::string markdown(const std::string& notes) const;
  void write_markdown(const std::string& notes) const;

 private:
  std::string dir_;
  std::vector<StabilityRow> rows_;
};

}  // namespace firn::study
