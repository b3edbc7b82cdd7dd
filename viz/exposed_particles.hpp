// Which particles can be seen at all: a particle with every cell (of the particle spacing,
// centred on the fill lattice) within two cells of its own occupied is buried inside its body
// from every direction and is neither drawn nor casts a shadow of its own. In a solid block of
// n^3 particles only the ~12 n^2 of its two-particle skin remain, which is what makes large sets
// cheap to draw. Particles on
// the camera's side of a cutaway plane are removed first, so the cut face shows.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "viz/frame_renderer.hpp"

namespace firn::viz {

struct CutPlane {
  Vec3 point, normal;  // particles with (x - point) . normal > 0 are removed
};

// Indices of the exposed particles, ascending. Without culling (the occupancy grid would exceed
// `max_cells` cells) every particle not cut away is exposed.
std::vector<std::uint32_t> exposed_particles(const PositionColumns& positions, double spacing,
                                             const std::optional<CutPlane>& cut, std::size_t max_cells = 1u << 24);

}  // namespace firn::viz
