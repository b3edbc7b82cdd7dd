// gnuplot files drawing one scene metric against time for every run of a sweep, grouped like the
// thesis' Figures 5.5 and 5.6: one panel per value of the first varied key, one curve per
// combination of the other keys, labelled with their values; with one varied key, like its
// Figure 4.2: one panel, one curve per value; with no varied key, one run's history (firn report).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "studies/sweep/gnuplot.hpp"
#include "studies/sweep/run_record.hpp"
#include "studies/sweep/value_list.hpp"

namespace firn::sweep {

// The scene-metric columns a sweep plots without --plot, when the runs have them.
inline const std::vector<std::string> default_plotted_metrics = {"displaced", "accumulated", "traction"};

// data: METRIC.dat, "time value" lines, one block per curve in the order plotted; script: METRIC.gp,
// which reads METRIC.dat and writes METRIC.png in the folder it runs in. None when no run has a
// value of the metric. The script picks gnuplot's pngcairo terminal, or
// png where pngcairo is absent.
std::optional<PlotFiles> metric_plot(const std::string& metric, const std::vector<VariedKey>& keys,
                                      const std::vector<RunRecord>& runs);

}  // namespace firn::sweep
