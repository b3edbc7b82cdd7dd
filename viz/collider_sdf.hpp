// The one place in viz/ that knows the engine's collider type: its signed distance at its pose.
#pragma once

#include "kernels/colliders.hpp"
#include "viz/sdf_mesh.hpp"

namespace firn::viz {

SignedDistance collider_sdf(const Collider<double>& collider);

}  // namespace firn::viz
