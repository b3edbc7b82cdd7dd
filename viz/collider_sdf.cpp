#include "viz/collider_sdf.hpp"

namespace firn::viz {

ColliderSolid collider_solid(const Collider<double>& collider) {
  ColliderSolid s;
  s.distance = [collider](const Vec3& x, Vec3& normal) { return collider.distance(x.data(), normal.data()); };
  collider.bounds(s.lo.data(), s.hi.data());
  s.shape = collider.shape;
  if (collider.shape == ColliderShape::plane) return s;
  // The body's own frame: the same collider at the origin, unrotated.
  Collider<double> at_rest = collider;
  for (int d = 0; d < 3; ++d) at_rest.center[d] = 0;
  for (int i = 0; i < 9; ++i) at_rest.rotation[i] = i % 4 == 0 ? 1 : 0;
  ColliderSolid::Body b;
  b.distance = [at_rest](const Vec3& y, Vec3& normal) { return at_rest.distance(y.data(), normal.data()); };
  at_rest.bounds(b.lo.data(), b.hi.data());
  for (int i = 0; i < 9; ++i) b.rotation[std::size_t(i)] = collider.rotation[i];
  for (std::size_t d = 0; d < 3; ++d) b.centre[d] = collider.center[d];
  s.body = b;
  return s;
}

}  // namespace firn::viz
