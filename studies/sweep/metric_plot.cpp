#include "studies/sweep/metric_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "studies/sweep/csv.hpp"
#include "studies/sweep/gnuplot.hpp"

namespace firn::sweep {
namespace {

struct Curve {
  std::string title;
  std::vector<std::pair<double, double>> points;  // (time, value)
};

}  // namespace

std::optional<PlotFiles> metric_plot(const std::string& metric, const std::vector<VariedKey>& keys,
                                      const std::vector<RunRecord>& runs) {
  // With one varied key every run is a curve of one panel (the thesis' Figure 4.2); with more, the
  // curves of each panel, panels in the order of the first key's values; with none, one run's
  // history (firn report).
  const bool panel_per_value = keys.size() > 1;
  const std::size_t curve_keys_from = panel_per_value ? 1 : 0;
  std::vector<std::vector<Curve>> panels(panel_per_value ? keys[0].values.size() : 1);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, t_lo = lo, t_hi = -lo;
  for (const RunRecord& run : runs) {
    if (!run.metrics || run.values.size() != keys.size()) continue;
    const int c = run.metrics->column_index(metric), t = run.metrics->column_index("time");
    if (c < 0) continue;
    std::size_t panel = 0;
    if (!keys.empty()) {
      const auto value = std::find(keys[0].values.begin(), keys[0].values.end(), run.values[0]);
      if (value == keys[0].values.end()) continue;
      if (panel_per_value) panel = std::size_t(value - keys[0].values.begin());
    }
    Curve curve;
    for (std::size_t k = curve_keys_from; k < keys.size(); ++k)
      curve.title += (k > curve_keys_from ? ", " : "") + keys[k].key + " = " + run.values[k];
    for (const auto& row : run.metrics->rows) {
      if (std::isnan(row[c]) || std::isnan(row[t])) continue;
      curve.points.emplace_back(row[t], row[c]);
      lo = std::min(lo, row[c]), hi = std::max(hi, row[c]);
      t_lo = std::min(t_lo, row[t]), t_hi = std::max(t_hi, row[t]);
    }
    if (!curve.points.empty()) panels[panel].push_back(std::move(curve));
  }
  std::size_t used = 0;
  for (const auto& p : panels) used += !p.empty();
  if (used == 0) return std::nullopt;

  const std::size_t cols = std::min<std::size_t>(used, 3), rows = (used + cols - 1) / cols;
  PlotFiles plot;
  plot.data = "# " + metric + " against time (s)" + (keys.empty() ? "" : " for every run of the sweep") +
              "; one block per curve of " + metric +
              ".gp, in the order plotted\n";
  std::string& s = plot.script;
  s = "# " + metric + " against time" +
      (keys.empty()       ? std::string(" in the run")
       : panel_per_value ? " for every run of the sweep: one panel per value of " + keys[0].key +
                               ", one curve per\n# combination of the other varied keys"
                         : " for every run of the sweep: one curve per value of " + keys[0].key) +
      ". Data: " + metric + ".dat. Re-plot from this folder with: gnuplot " + metric + ".gp\n";
  s += gnuplot_png_output(metric + ".png", int(520 * cols), int(440 * rows));
  s += "set multiplot layout " + std::to_string(rows) + "," + std::to_string(cols) + " title " + gnuplot_quoted(metric) + "\n";
  s += "set xlabel 'time (s)'\nset ylabel " + gnuplot_quoted(metric) + "\nset key below\nset grid\n";
  // Every panel on the same axes; the margins keep %.6g rounding from clipping a point.
  if (t_hi > t_lo)
    s += "set xrange [" + csv_number(t_lo - 0.001 * (t_hi - t_lo)) + ":" + csv_number(t_hi + 0.001 * (t_hi - t_lo)) +
         "]\n";
  if (hi > lo)
    s += "set yrange [" + csv_number(lo - 0.05 * (hi - lo)) + ":" + csv_number(hi + 0.05 * (hi - lo)) + "]\n";
  int block = 0;
  for (std::size_t p = 0; p < panels.size(); ++p) {
    if (panels[p].empty()) continue;
    const std::string panel = panel_per_value ? keys[0].key + " = " + keys[0].values[p] : "";
    s += "set title " + gnuplot_quoted(panel) + "\nplot ";
    // gnuplot's default colours repeat after eight; later curves change the dash pattern instead.
    constexpr std::size_t kColours = 8;
    for (std::size_t i = 0; i < panels[p].size(); ++i) {
      const Curve& curve = panels[p][i];
      if (block > 0) plot.data += "\n\n";  // gnuplot's data-set separator: two blank lines
      s += (i ? ", \\\n     " : "") + gnuplot_quoted(metric + ".dat") + " index " + std::to_string(block++) +
           " using 1:2 with lines linewidth 2 linecolor " + std::to_string(i % kColours + 1) + " dashtype " +
           std::to_string(i / kColours + 1) + " " + (curve.title.empty() ? "notitle" : "title " + gnuplot_quoted(curve.title));
      plot.data += "# " + panel + (panel.empty() || curve.title.empty() ? "" : ", ") + curve.title + "\n";
      for (const auto& [time, value] : curve.points) plot.data += csv_number(time) + " " + csv_number(value) + "\n";
    }
    s += "\n";
  }
  s += "unset multiplot\n";
  return plot;
}

}  // namespace firn::sweep
