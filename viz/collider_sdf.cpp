#include "viz/collider_sdf.hpp"

namespace firn::viz {

SignedDistance collider_sdf(const Collider<double>& collider) {
  return [collider](const Vec3& x, Vec3& normal) { return collider.distance(x.data(), normal.data()); };
}

}  // namespace firn::viz
