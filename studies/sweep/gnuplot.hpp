// Plots drawn by gnuplot (Debian package gnuplot-nox) from a data file and a script that firn
// writes next to each other, so a user can edit the script and re-plot: `gnuplot NAME.gp`.
#pragma once

#include <string>

namespace firn::sweep {

// A gnuplot single-quoted string: only the quote itself needs escaping, by doubling it.
std::string gnuplot_quoted(const std::string& text);

// Script lines that choose the pngcairo terminal (png where pngcairo is absent) at width x height
// pixels, and set the output to `png_name`.
std::string gnuplot_png_output(const std::string& png_name, int width, int height);

// A plot's data file and the script that draws it.
struct PlotFiles {
  std::string data;
  std::string script;
};

enum class PlotStatus { drawn, no_gnuplot, failed };

// Writes DIR/NAME.dat and DIR/NAME.gp, then runs `gnuplot NAME.gp` in DIR (started from an argument
// vector). Its output goes to DIR/NAME.log, removed when empty.
PlotStatus draw_plot(const std::string& dir, const std::string& name, const std::string& data,
                     const std::string& script);

// draw_plot(dir, name, files), saying on standard error, as `program` ("firn sweep"), when gnuplot
// is missing or fails.
PlotStatus draw_plot_or_warn(const std::string& program, const std::string& dir, const std::string& name,
                             const PlotFiles& files);

}  // namespace firn::sweep
