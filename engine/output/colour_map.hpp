// Perceptual colour maps for scalar fields: viridis (van der Walt and Smith, matplotlib 2.0),
// sampled at nine points and interpolated linearly in sRGB.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace firn {

// The colour of s in [0, 1] (clamped) as 8-bit sRGB.
inline std::array<std::uint8_t, 3> viridis(double s) {
  static constexpr std::uint8_t kStops[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},
                                                {44, 113, 142}, {33, 144, 141}, {39, 173, 129},
                                                {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  const double x = std::isfinite(s) ? std::fmin(1.0, std::fmax(0.0, s)) * 8 : 0;
  const int i = std::min(7, int(x));
  const double f = x - i;
  std::array<std::uint8_t, 3> c;
  for (int k = 0; k < 3; ++k) c[k] = std::uint8_t(std::lround(kStops[i][k] + f * (kStops[i + 1][k] - kStops[i][k])));
  return c;
}

}  // namespace firn
