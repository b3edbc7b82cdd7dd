// The one place in viz/ that knows the engine's collider type: its signed distance at its pose,
// a box that holds it, and for a bounded solid the same in its own frame with the pose, so that
// its mesh is made once and moved with it.
#pragma once

#include <array>
#include <optional>

#include "kernels/colliders.hpp"
#include "viz/sdf_mesh.hpp"

namespace firn::viz {

struct ColliderSolid {
  SignedDistance distance;
  Vec3 lo, hi;  // a box holding the solid (infinite sides for a half-space)
  struct Body {
    SignedDistance distance;  // in the body's frame
    Vec3 lo, hi;              // a box holding it there
    std::array<double, 9> rotation;  // world x = rotation y + centre (row-major)
    Vec3 centre;
    Vec3 to_world(const Vec3& y) const { return rotate(y) + centre; }
    Vec3 rotate(const Vec3& y) const {
      return {rotation[0] * y[0] + rotation[1] * y[1] + rotation[2] * y[2],
              rotation[3] * y[0] + rotation[4] * y[1] + rotation[5] * y[2],
              rotation[6] * y[0] + rotation[7] * y[1] + rotation[8] * y[2]};
    }
  };
  std::optional<Body> body;  // none for a half-space
  ColliderShape shape = ColliderShape::plane;
};

ColliderSolid collider_solid(const Collider<double>& collider);

}  // namespace firn::viz
