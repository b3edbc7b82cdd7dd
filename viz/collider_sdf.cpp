#include "viz/collider_sdf.hpp"

namespace firn::viz {

SignedDistance collider_sdf(const Collider<double>& collider, double time) {
  return [collider, time](const Vec3& x, Vec3& normal) { return collider.distance(x.data(), time, normal.data()); };
}

}  // namespace firn::viz
