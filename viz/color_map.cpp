#include "viz/color_map.hpp"

#include <algorithm>
#include <stdexcept>

#include "engine/output/colour_map.hpp"

namespace firn::viz {

ColorMap parse_color_map(const std::string& name) {
  if (name == "viridis") return ColorMap::viridis;
  if (name == "diverging") return ColorMap::diverging;
  throw std::invalid_argument("unknown colour map '" + name + "' (viridis or diverging)");
}

namespace {

// Moreland's cool-warm diverging map ("Diverging Color Maps for Scientific Visualization", 2009,
// table of section 6) at five of its control points, interpolated linearly.
Rgb diverging(double t) {
  static const double p[5][3] = {{0.230, 0.299, 0.754},
                                 {0.552, 0.690, 0.996},
                                 {0.865, 0.865, 0.865},
                                 {0.958, 0.603, 0.482},
                                 {0.706, 0.016, 0.150}};
  const double s = t * 4;
  const int i = std::min(3, int(s));
  const double f = s - i;
  Rgb out;
  for (int k = 0; k < 3; ++k) out[std::size_t(k)] = float(p[i][k] + f * (p[i + 1][k] - p[i][k]));
  return out;
}

}  // namespace

Rgb color_map_rgb(ColorMap map, double t) {
  t = std::clamp(t, 0.0, 1.0);
  return map == ColorMap::viridis ? firn::viridis(t) : diverging(t);
}

Rgb default_material_color(int m) {
  // Chosen for snow scenes: a warm core, a blue middle layer and a white shell read apart, then
  // Okabe and Ito's colour-blind-safe hues.
  static const Rgb palette[] = {{0.93f, 0.55f, 0.30f}, {0.38f, 0.64f, 0.90f}, {0.93f, 0.95f, 0.98f},
                                {0.00f, 0.62f, 0.45f}, {0.80f, 0.47f, 0.65f}, {0.94f, 0.89f, 0.26f},
                                {0.84f, 0.37f, 0.00f}, {0.34f, 0.71f, 0.91f}};
  return palette[std::size_t(m) % (sizeof palette / sizeof palette[0])];
}

}  // namespace firn::viz
