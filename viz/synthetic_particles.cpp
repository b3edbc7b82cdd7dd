#include "viz/synthetic_particles.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace firn::viz {

PositionColumns SyntheticParticles::columns() const {
  PositionColumns p;
  for (int d = 0; d < 3; ++d) p.x[d] = x[d].data();
  p.count = x[0].size();
  return p;
}

SyntheticParticles jittered_block(long count, double side, const Vec3& corner, std::uint32_t seed) {
  const long n = std::max(1L, std::lround(std::cbrt(double(count))));
  SyntheticParticles s;
  s.spacing = side / double(n);
  // A fixed generator and our own uniform mapping: the same particles on every platform.
  std::mt19937 rng(seed);
  auto jitter = [&] { return (double(rng()) / 4294967295.0 - 0.5) * 0.5 * s.spacing; };
  for (long k = 0; k < n; ++k)
    for (long j = 0; j < n; ++j)
      for (long i = 0; i < n; ++i) {
        const long index[3] = {i, k, j};  // y (up) is the slowest: layers from the bottom
        for (std::size_t d = 0; d < 3; ++d)
          s.x[d].push_back(float(corner[d] + (double(index[d]) + 0.5) * s.spacing + jitter()));
      }
  return s;
}

}  // namespace firn::viz
