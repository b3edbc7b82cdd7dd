// The one place in viz/ that knows the engine's collider type: its signed distance at its pose,
// and a box that holds it.
#pragma once

#include "kernels/colliders.hpp"
#include "viz/sdf_mesh.hpp"

namespace firn::viz {

struct ColliderSolid {
  SignedDistance distance;
  Vec3 lo, hi;  // a box holding the solid (infinite sides for a half-space)
};

ColliderSolid collider_solid(const Collider<double>& collider);

}  // namespace firn::viz
