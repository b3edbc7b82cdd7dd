// Viridis (van der Walt and Smith, matplotlib 2015), the perceptual colour map of every scalar
// field firn draws (footprint maps here, particle fields in viz/color_map.cpp), as the degree-6
// least-squares polynomial fit published by Matt Zucker (shadertoy WlfXRN, CC0): within about 1%
// of the table.
#pragma once

#include <algorithm>
#include <array>

namespace firn {

// sRGB components in [0, 1] of the map at t in [0, 1] (clamped).
inline std::array<float, 3> viridis(double t) {
  static constexpr double c[7][3] = {{0.2777273272234177, 0.005407344544966578, 0.3340998053353061},
                                     {0.1050930431085774, 1.404613529898575, 1.384590162594685},
                                     {-0.3308618287255563, 0.214847559468213, 0.09509516302823659},
                                     {-4.634230498983486, -5.799100973351585, -19.33244095627987},
                                     {6.228269936347081, 14.17993336680509, 56.69055260068105},
                                     {4.776384997670288, -13.74514537774601, -65.35303263337234},
                                     {-5.435455855934631, 4.645852612178535, 26.3124352495832}};
  t = std::clamp(t, 0.0, 1.0);
  std::array<float, 3> out;
  for (int k = 0; k < 3; ++k) {
    double v = c[6][k];
    for (int i = 5; i >= 0; --i) v = c[i][k] + t * v;
    out[std::size_t(k)] = float(std::clamp(v, 0.0, 1.0));
  }
  return out;
}

}  // namespace firn
