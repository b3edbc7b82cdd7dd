#include "engine/noise_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/splitmix64.hpp"

namespace firn {
namespace {

double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }  // Perlin 2002's fade

}  // namespace

NoiseField::NoiseField(double scale, std::uint64_t seed) : scale_(scale), seed_(seed) {
  if (!(scale > 0) || !std::isfinite(scale)) throw std::invalid_argument("noise scale must be positive and finite");
}

double NoiseField::node(std::int64_t i, std::int64_t j, std::int64_t k) const {
  std::uint64_t h = splitmix64_mix(seed_ + 0x9e3779b97f4a7c15ull);
  for (const std::int64_t c : {i, j, k}) h = splitmix64_mix(h ^ std::uint64_t(c));
  return double(h >> 11) * 0x1.0p-52 - 1;  // 53 bits: [-1, 1)
}

double NoiseField::operator()(const std::array<double, 3>& x) const {
  std::int64_t base[3];
  double w[3];
  for (int d = 0; d < 3; ++d) {
    const double u = x[d] / scale_, f = std::floor(u);
    base[d] = std::int64_t(f);
    w[d] = fade(u - f);
  }
  double n = 0;
  for (int c = 0; c < 8; ++c) {
    const int a = c & 1, b = (c >> 1) & 1, e = (c >> 2) & 1;
    const double weight = (a ? w[0] : 1 - w[0]) * (b ? w[1] : 1 - w[1]) * (e ? w[2] : 1 - w[2]);
    n += weight * node(base[0] + a, base[1] + b, base[2] + e);
  }
  return std::clamp(n, -1.0, 1.0);  // a convex combination already: this only catches rounding
}

}  // namespace firn
