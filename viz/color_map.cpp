#include "viz/color_map.hpp"

#include <algorithm>
#include <stdexcept>

namespace firn::viz {

ColorMap parse_color_map(const std::string& name) {
  if (name == "viridis") return ColorMap::viridis;
  if (name == "diverging") return ColorMap::diverging;
  throw std::invalid_argument("unknown colour map '" + name + "' (viridis or diverging)");
}

namespace {

// Viridis (van der Walt and Smith, matplotlib 2015) as the degree-6 least-squares polynomial fit
// published by Matt Zucker (shadertoy WlfXRN, CC0); within about 1% of the table.
Rgb viridis(double t) {
  static const double c[7][3] = {{0.2777273272234177, 0.005407344544966578, 0.3340998053353061},
                                 {0.1050930431085774, 1.404613529898575, 1.384590162594685},
                                 {-0.3308618287255563, 0.214847559468213, 0.09509516302823659},
                                 {-4.634230498983486, -5.799100973351585, -19.33244095627987},
                                 {6.228269936347081, 14.17993336680509, 56.69055260068105},
                                 {4.776384997670288, -13.74514537774601, -65.35303263337234},
                                 {-5.435455855934631, 4.645852612178535, 26.3124352495832}};
  Rgb out;
  for (int k = 0; k < 3; ++k) {
    double v = c[6][k];
    for (int i = 5; i >= 0; --i) v = c[i][k] + t * v;
    out[std::size_t(k)] = float(std::clamp(v, 0.0, 1.0));
  }
  return out;
}

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
  return map == ColorMap::viridis ? viridis(t) : diverging(t);
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
