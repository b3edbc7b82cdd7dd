#include "viz/collider_sdf.hpp"

namespace firn::viz {

ColliderSolid collider_solid(const Collider<double>& collider) {
  ColliderSolid s;
  s.distance = [collider](const Vec3& x, Vec3& normal) { return collider.distance(x.data(), normal.data()); };
  collider.bounds(s.lo.data(), s.hi.data());
  return s;
}

}  // namespace firn::viz
