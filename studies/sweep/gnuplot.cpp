#include "studies/sweep/gnuplot.hpp"

#include <cstdio>
#include <filesystem>
#include <system_error>

#include "engine/output/atomic_file.hpp"
#include "studies/sweep/child_process.hpp"

namespace firn::sweep {

std::string gnuplot_quoted(const std::string& text) {
  std::string s = "'";
  for (const char c : text) s += c == '\'' ? std::string("''") : std::string(1, c);
  return s + "'";
}

std::string gnuplot_png_output(const std::string& png_name, int width, int height) {
  const std::string size = " noenhanced size " + std::to_string(width) + "," + std::to_string(height);
  return "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n  set terminal pngcairo" + size +
         "\n} else {\n  set terminal png" + size + "\n}\nset output " + gnuplot_quoted(png_name) + "\n";
}

PlotStatus draw_plot(const std::string& dir, const std::string& name, const std::string& data,
                     const std::string& script) {
  std::filesystem::create_directories(dir);
  write_file_atomically(dir + "/" + name + ".dat", data);
  write_file_atomically(dir + "/" + name + ".gp", script);
  const std::string log = dir + "/" + name + ".log";
  const int status = wait_child(start_child({{"gnuplot", name + ".gp"}, log, dir, true}));
  if (status == 127) return PlotStatus::no_gnuplot;
  std::error_code ec;
  if (status == 0 && std::filesystem::file_size(log, ec) == 0) std::filesystem::remove(log, ec);
  return status == 0 ? PlotStatus::drawn : PlotStatus::failed;
}

PlotStatus draw_plot_or_warn(const std::string& program, const std::string& dir, const std::string& name,
                             const PlotFiles& files) {
  const PlotStatus status = draw_plot(dir, name, files.data, files.script);
  if (status == PlotStatus::no_gnuplot)
    std::fprintf(stderr, "%s: gnuplot not found (Debian package gnuplot-nox): no %s.png\n", program.c_str(),
                 name.c_str());
  if (status == PlotStatus::failed)
    std::fprintf(stderr, "%s: gnuplot failed on %s/%s.gp (see %s.log)\n", program.c_str(), dir.c_str(), name.c_str(),
                 name.c_str());
  return status;
}

}  // namespace firn::sweep
