#include "studies/accuracy/accuracy_plot.hpp"

#include <algorithm>
#include <cmath>

#include "studies/sweep/csv.hpp"

namespace firn::study {
namespace {

using sweep::csv_number;
using sweep::gnuplot_quoted;

// Colour per (transfer, shape): gnuplot's default palette indices 1-6.
int colour_of(const VerificationMethod& m) { return 2 * int(m.transfer) + int(m.shape) + 1; }

std::string style_of(const VerificationMethod& m) {
  const bool single = m.precision == Precision::single;
  return " linecolor " + std::to_string(colour_of(m)) + " dashtype " + (single ? "2" : "1") + " pointtype " +
         (single ? "6" : "7");
}

}  // namespace

sweep::PlotFiles accuracy_plot(const AccuracyProblem& problem, const std::vector<AccuracyRow>& rows) {
  sweep::PlotFiles plot;
  const std::string dat = gnuplot_quoted(problem.name + ".dat");
  plot.data = "# " + problem.name + ": one block per method (dx, seconds, error by level), then the Pareto front\n";
  std::string left, right;
  int block = 0;
  double dx_lo = INFINITY, dx_hi = 0;
  for (const VerificationMethod& m : all_methods()) {
    std::vector<const AccuracyRow*> mine;
    for (const AccuracyRow& r : rows)
      if (same_method(r.method, m) && std::isfinite(r.result.error) && r.result.error > 0) mine.push_back(&r);
    if (mine.empty()) continue;
    std::sort(mine.begin(), mine.end(), [](const AccuracyRow* a, const AccuracyRow* b) { return a->level < b->level; });
    if (block > 0) plot.data += "\n\n";  // gnuplot's data-set separator
    plot.data += "# " + method_name(m) + "\n";
    for (const AccuracyRow* r : mine) {
      plot.data += csv_number(r->result.dx) + " " + csv_number(r->result.seconds) + " " + csv_number(r->result.error) + "\n";
      dx_lo = std::min(dx_lo, r->result.dx);
      dx_hi = std::max(dx_hi, r->result.dx);
    }
    const std::string index = dat + " index " + std::to_string(block++);
    left += (left.empty() ? "plot " : ", \\\n     ") + index + " using 1:3 with linespoints" + style_of(m) +
            " title " + gnuplot_quoted(method_name(m));
    right += (right.empty() ? "plot " : ", \\\n     ") + index + " using 2:3 with points" + style_of(m) + " notitle";
  }
  std::vector<const AccuracyRow*> front;
  for (const AccuracyRow& r : rows)
    if (r.pareto && r.result.error > 0) front.push_back(&r);
  std::sort(front.begin(), front.end(),
            [](const AccuracyRow* a, const AccuracyRow* b) { return a->result.seconds < b->result.seconds; });
  if (!front.empty()) {
    plot.data += "\n\n# Pareto front\n";
    for (const AccuracyRow* r : front)
      plot.data += csv_number(r->result.dx) + " " + csv_number(r->result.seconds) + " " + csv_number(r->result.error) + "\n";
    right += ", \\\n     " + dat + " index " + std::to_string(block) +
             " using 2:3 with steps linewidth 2 linecolor rgb 'black' title 'Pareto front', \\\n     " + dat +
             " index " + std::to_string(block) +
             " using 2:3 with points pointtype 4 pointsize 2 linecolor rgb 'black' notitle";
  }
  // The expected order as a line through the default method's finest point.
  const AccuracyRow* anchor = nullptr;
  for (const AccuracyRow& r : rows)
    if (same_method(r.method, VerificationMethod{}) && std::isfinite(r.result.error) && r.result.error > 0 &&
        (!anchor || r.level > anchor->level))
      anchor = &r;
  if (problem.expected_order > 0 && anchor && !left.empty())
    left += ", \\\n     " + csv_number(anchor->result.error) + " * (x / " + csv_number(anchor->result.dx) + ")**" +
            csv_number(problem.expected_order) + " with lines linewidth 2 dashtype 3 linecolor rgb 'black' title " +
            gnuplot_quoted("order " + csv_number(problem.expected_order));

  std::string& s = plot.script;
  s = "# " + problem.name + ": error against dx and against run time for every method (firn study accuracy).\n"
      "# Data: " + problem.name + ".dat. Re-plot from this folder with: gnuplot " + problem.name + ".gp\n";
  s += sweep::gnuplot_png_output(problem.name + ".png", 1400, 620);
  s += "set multiplot layout 1,2 title " + gnuplot_quoted(problem.name + ": " + problem.error) + "\n";
  s += "set logscale xy\nset grid\nset ylabel 'error'\nset format y '%.0e'\n";
  if (left.empty()) {
    s += "set title 'no case finished'\nplot 1 notitle\n";
  } else {
    s += "set xlabel 'dx (m)'\nset title 'convergence'\nset key bottom right\n";
    const double margin = dx_hi > dx_lo ? 1.2 : 2;  // one level: an octave either side
    s += "set xrange [" + csv_number(dx_lo / margin) + ":" + csv_number(dx_hi * margin) + "]\n";
    s += left + "\n";
    s += "set autoscale x\nset xlabel 'run time (s)'\nset title 'error against run time'\nset key bottom left\n" +
         right + "\n";
  }
  s += "unset multiplot\n";
  return plot;
}

sweep::PlotFiles energy_history_plot(const std::vector<EnergySeries>& series) {
  sweep::PlotFiles plot;
  plot.data = "# two spheres: time (s) and total energy / initial, one block per series\n";
  std::string curves;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const EnergySeries& e = series[i];
    if (i > 0) plot.data += "\n\n";
    plot.data += "# " + e.title + "\n";
    const double e0 = e.total.empty() ? 1 : e.total.front();
    for (std::size_t k = 0; k < e.time.size(); ++k)
      plot.data += csv_number(e.time[k]) + " " + csv_number(e.total[k] / e0) + "\n";
    curves += (i ? ", \\\n     " : "plot ") + gnuplot_quoted("two_spheres_energy.dat") + " index " +
              std::to_string(i) + " using 1:2 with lines linewidth 2 title " + gnuplot_quoted(e.title);
  }
  std::string& s = plot.script;
  s = "# Two elastic spheres colliding: total energy against time per transfer scheme (firn study accuracy).\n"
      "# Re-plot from this folder with: gnuplot two_spheres_energy.gp\n";
  s += sweep::gnuplot_png_output("two_spheres_energy.png", 900, 560);
  s += "set title 'two spheres: (kinetic + elastic energy) / initial'\nset xlabel 'time (s)'\n"
       "set ylabel 'E / E(0)'\nset grid\nset key bottom left\n";
  s += (curves.empty() ? std::string("plot 1 notitle") : curves) + "\n";
  return plot;
}

}  // namespace firn::study
