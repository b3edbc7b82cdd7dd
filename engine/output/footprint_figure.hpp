// The footprint as a figure a reader can use (issue 18 item 4; the thesis' Figure 5.7): the
// contact pressure per grid column as a heat map with physical axes in mm about the axle
// (circumferential x to the right, lateral z upward), a colour bar in kPa, the tread outline drawn
// over it, and the contact patch's area and mean and peak pressure printed above.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "engine/output/image.hpp"

namespace firn {

// Pressures on grid columns: column (i, k) is centred at (x0 + i dx, z0 + k dx).
struct FootprintField {
  double x0 = 0, z0 = 0, dx = 0;
  int nx = 0, nz = 0;
  std::vector<double> pressure;  // [k * nx + i] (Pa)
  double at(int i, int k) const { return pressure[std::size_t(k) * std::size_t(nx) + std::size_t(i)]; }
};

// The contact patch: the columns carrying more than kPatchFraction of the peak (a column touched
// by one stray particle does not count). Area (m^2), mean pressure over the patch and peak (Pa).
struct FootprintStats {
  static constexpr double kPatchFraction = 0.05;
  double area = 0, mean = 0, peak = 0;
};
FootprintStats footprint_stats(const FootprintField& field);

// What lies above world point (x, z) of the ground: nothing, a tread block, or a groove.
enum class TreadCover { none, block, groove };
using TreadCoverAt = std::function<TreadCover(double x, double z)>;

struct FootprintFigureSpec {
  double axle_x = 0, axle_z = 0;  // the axes' origin (the axle's position)
  double pressure_max = 0;        // the colour bar's top (Pa); 0: the field's peak
  std::string title;              // first line, e.g. "six_rib, t = 100.0 ms"
  std::string patch = "contact patch";  // what the columns above 5% of the peak are called
  std::string empty = "no contact";     // what a grey (zero) column means
  TreadCoverAt tread;             // the outline (empty: none)
};

// At least kMinWidth pixels wide; the map keeps the columns' aspect ratio.
constexpr int kFootprintFigureMinWidth = 600;
Image draw_footprint_figure(const FootprintField& field, const FootprintFigureSpec& spec);

}  // namespace firn
