// firn report DIR (issue 18 item 5): the report page of a run's or a sweep's output folder,
// whichever DIR is (a sweep's holds sweep.args, a run's summary.json or scene.resolved.toml).
#pragma once

#include <string>

#include "studies/sweep/sweep_plan.hpp"

namespace firn::report {

// Writes DIR/report.html (run_report.hpp, sweep_report.hpp) and returns its path; throws
// std::invalid_argument when DIR is neither kind of folder, and what those throw.
std::string write_report(const std::string& dir, const std::string& shipped_scenes, const sweep::SweepReport& report);

}  // namespace firn::report
