// Kinematic rigid colliders acting on grid nodes (DESIGN.md section 3): a half-space plane or an
// axis-aligned box moving with constant velocity. A node whose position lies inside the solid
// (signed distance <= 0) takes the collider's boundary condition on its velocity relative to the
// collider: v <- v_c + bc(v - v_c), with bc from kernels/boundary_conditions.hpp and n the outward
// normal of the solid (the gradient of the signed distance).
#pragma once

#include <cmath>
#include <cstdint>

#include "kernels/boundary_conditions.hpp"
#include "kernels/hd.hpp"

namespace firn {

enum class ColliderShape : std::uint8_t { plane, box };

template <class T>
struct Collider {
  ColliderShape shape = ColliderShape::plane;
  WallType boundary = WallType::sticky;
  T friction = T(0);
  T point[3] = {T(0), T(0), T(0)};   // plane: a point on it at t = 0
  T normal[3] = {T(0), T(1), T(0)};  // plane: unit normal out of the solid
  T min[3] = {T(0), T(0), T(0)};     // box corners at t = 0
  T max[3] = {T(0), T(0), T(0)};
  T velocity[3] = {T(0), T(0), T(0)};

  // Signed distance from x to the solid's surface at time t (negative inside), and the outward
  // normal n. The box distance is exact (inside: distance to the nearest face).
  FIRN_HD T distance(const T x[3], T t, T n[3]) const {
    T y[3];
    for (int d = 0; d < 3; ++d) y[d] = x[d] - velocity[d] * t;
    if (shape == ColliderShape::plane) {
      T s = T(0);
      for (int d = 0; d < 3; ++d) {
        n[d] = normal[d];
        s += (y[d] - point[d]) * normal[d];
      }
      return s;
    }
    T q[3], outside2 = T(0), inside = -T(INFINITY);
    int face = 0;
    for (int d = 0; d < 3; ++d) {
      const T c = T(0.5) * (min[d] + max[d]), h = T(0.5) * (max[d] - min[d]);
      const T r = y[d] - c;
      q[d] = std::fabs(r) - h;
      n[d] = q[d] > T(0) ? (r > T(0) ? q[d] : -q[d]) : T(0);
      outside2 += q[d] > T(0) ? q[d] * q[d] : T(0);
      if (q[d] > inside) inside = q[d], face = d;
    }
    if (outside2 > T(0)) {
      const T len = std::sqrt(outside2);
      for (int d = 0; d < 3; ++d) n[d] /= len;
      return len;
    }
    for (int d = 0; d < 3; ++d) n[d] = T(0);
    n[face] = y[face] > T(0.5) * (min[face] + max[face]) ? T(1) : T(-1);
    return inside;
  }

  // Applies the boundary condition to the node velocity v at x, time t, if x is inside.
  FIRN_HD void apply(T v[3], const T x[3], T t) const {
    T n[3];
    if (distance(x, t, n) > T(0)) return;
    T rel[3] = {v[0] - velocity[0], v[1] - velocity[1], v[2] - velocity[2]};
    apply_wall(rel, n, boundary, friction);
    for (int d = 0; d < 3; ++d) v[d] = rel[d] + velocity[d];
  }
};

}  // namespace firn
