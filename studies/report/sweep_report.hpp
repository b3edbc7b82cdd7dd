// firn report on a sweep's output folder (issue 18 item 5): DIR/report.html with the sweep's
// contact sheets (contact_sheets/NNNNN.png, when its runs were rendered), its metric plots grouped
// like the thesis' Figures 5.5 and 5.6 (plots/METRIC.png), the thesis' Table 5.1 for each plotted
// metric (pivot_table.hpp), sweep.csv as a table, and a link to each run's own report, which it
// writes too (run_report.hpp).
#pragma once

#include <string>

#include "studies/sweep/sweep_plan.hpp"

namespace firn::report {

// Collects the sweep in DIR first (firn sweep --collect: sweep.csv and the plots from the runs
// that finished), then writes the pages; returns the sweep page's path. Throws
// std::invalid_argument (not a sweep's folder), SceneError (its scene no longer loads) or
// std::runtime_error (a file cannot be read or written). `report` hears of each plot it cannot draw.
std::string write_sweep_report(const std::string& dir, const std::string& shipped_scenes,
                               const sweep::SweepReport& report);

}  // namespace firn::report
