// A synthetic particle set for `firn bench render` and the renderer's tests: a cube of particles
// on a cubic lattice, each jittered by up to a quarter of the spacing, in SoA columns.
#pragma once

#include <cstdint>
#include <vector>

#include "viz/frame_renderer.hpp"

namespace firn::viz {

struct SyntheticParticles {
  std::vector<float> x[3];
  double spacing;
  PositionColumns columns() const;
};

// About `count` particles (the nearest cube) filling the cube of side `side` whose lowest
// corner is `corner`, ordered bottom layer first; the same seed gives the same particles.
SyntheticParticles jittered_block(long count, double side, const Vec3& corner, std::uint32_t seed = 1);

}  // namespace firn::viz
