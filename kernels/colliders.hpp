// Kinematic rigid colliders acting on grid nodes (DESIGN.md section 3): signed distance functions
// evaluated in the collider's moving frame, with linear and angular velocity.
//
// The pose is the one at the end of the step (the engine advances it before the grid update):
// a node at x has body coordinates y = R^T (x - c), with c the body origin and R the rotation
// whose columns are the body axes in world coordinates. In the body frame:
//   plane:    the solid y1 <= 0 (normal: the body y axis);
//   box:      |y_d| <= half[d];
//   cylinder: sqrt(y0^2 + y1^2) <= radius, |y2| <= half[2] (axis: the body z axis);
//   tire:     TireShape (axle: the body z axis).
// A node inside (signed distance below -skin) takes the boundary condition on its velocity relative to
// the collider's rigid velocity at that node, v_c(x) = v + omega x (x - c), which is exact for
// rigid motion: v <- v_c + bc(v - v_c), bc from kernels/boundary_conditions.hpp with the outward
// normal n = R grad(d). The change of the node's momentum is the impulse the collider applies;
// its opposite acts on the collider (grid_update.hpp sums it into force and torque).
//
// A node on the surface is outside. Scenes often put a plane (the ground, the incline) through a
// row of nodes with a body resting on it; the signed distance of those nodes is then zero up to the
// rounding of x = origin + i dx and of the pose, whose sign differs between float and double and
// between builds with and without fused multiply-adds. The contact must not hinge on it: with the
// row inside, the rolling cylinder of firn verify hardly turned (slip ratio 0.90, acceleration
// error 12%), with it outside it rolled (1.3%), and which one happened was decided by rounding. A
// skin of kColliderSkin dx, far above the rounding and far below any length the physics resolves,
// settles it: nodes with d >= -skin are outside. (A row on the surface carries load through the
// whole stencil of the particles above it, 1.5 dx high, which puts the normal force far ahead of a
// rolling body; the row below carries only the lowest particles.)
#pragma once

#include <cmath>
#include <cstdint>

#include "kernels/boundary_conditions.hpp"
#include "kernels/friction.hpp"
#include "kernels/hd.hpp"
#include "kernels/tire_shape.hpp"

namespace firn {

enum class ColliderShape : std::uint8_t { plane, box, cylinder, tire };

// How a collider's contact conditions are decided: node by node (`apply`, below), pooled over
// the contact of one stiff body (kernels/pooled_contact.hpp), or by a penalty force at the particles
// that overlap it (kernels/step/penalty_contact.hpp), which leaves the grid nodes alone.
enum class ColliderContact : std::uint8_t { nodes, pooled, penalty };

// The surface skin in cells (see above): 1e-3 dx covers float rounding of coordinates up to about
// 8000 cells from the grid's origin.
constexpr double kColliderSkin = 1e-3;

template <class T>
struct Collider {
  ColliderShape shape = ColliderShape::plane;
  WallType boundary = WallType::sticky;
  Friction<T> friction{};
  ColliderContact contact = ColliderContact::nodes;
  T center[3] = {T(0), T(0), T(0)};                                  // body origin c
  T rotation[9] = {T(1), T(0), T(0), T(0), T(1), T(0), T(0), T(0), T(1)};  // R, row-major
  T velocity[3] = {T(0), T(0), T(0)};                                // of the origin
  T angular_velocity[3] = {T(0), T(0), T(0)};                        // omega, world frame
  T half[3] = {T(0), T(0), T(0)};  // box half extents; cylinder: half[2] is the half length
  T radius = T(0);                 // cylinder
  TireShape<T> tire{};

  // Signed distance from x to the surface (negative inside) and the outward unit normal n.
  FIRN_HD T distance(const T x[3], T n[3]) const {
    T y[3], m[3];
    for (int i = 0; i < 3; ++i)  // y = R^T (x - c)
      y[i] = rotation[i] * (x[0] - center[0]) + rotation[3 + i] * (x[1] - center[1]) +
             rotation[6 + i] * (x[2] - center[2]);
    const T d = body_distance(y, m);
    for (int i = 0; i < 3; ++i) n[i] = rotation[3 * i] * m[0] + rotation[3 * i + 1] * m[1] + rotation[3 * i + 2] * m[2];
    return d;
  }

  // A world box holding the solid at its pose (a plane's is unbounded): a rotated box's corners,
  // a cylinder's or tire's rims, lo[d] = c[d] - e[d], hi[d] = c[d] + e[d].
  FIRN_HD void bounds(T lo[3], T hi[3]) const {
    for (int d = 0; d < 3; ++d) {
      const T* row = rotation + 3 * d;  // world axis d in body coordinates
      T e = T(INFINITY);
      if (shape == ColliderShape::box) {
        e = std::fabs(row[0]) * half[0] + std::fabs(row[1]) * half[1] + std::fabs(row[2]) * half[2];
      } else if (shape != ColliderShape::plane) {  // disc of radius r across the body z axis, half length h along it
        const T r = shape == ColliderShape::tire ? tire.radius : radius;
        const T h = shape == ColliderShape::tire ? T(0.5) * tire.width : half[2];
        e = std::fabs(row[2]) * h + r * std::sqrt(std::fmax(T(0), T(1) - row[2] * row[2]));
      }
      lo[d] = center[d] - e;
      hi[d] = center[d] + e;
    }
  }

  // The rigid body's velocity at x: v + omega x (x - c).
  FIRN_HD void velocity_at(const T x[3], T out[3]) const {
    const T r[3] = {x[0] - center[0], x[1] - center[1], x[2] - center[2]};
    const T* w = angular_velocity;
    out[0] = velocity[0] + w[1] * r[2] - w[2] * r[1];
    out[1] = velocity[1] + w[2] * r[0] - w[0] * r[2];
    out[2] = velocity[2] + w[0] * r[1] - w[1] * r[0];
  }

  // Applies the boundary condition to the node velocity v at x if x is inside by more than `skin`
  // (kColliderSkin dx for grid nodes); returns whether it did.
  FIRN_HD bool apply(T v[3], const T x[3], T skin) const {
    T n[3];
    if (distance(x, n) >= -skin) return false;
    T vc[3];
    velocity_at(x, vc);
    T rel[3] = {v[0] - vc[0], v[1] - vc[1], v[2] - vc[2]};
    apply_wall(rel, n, boundary, friction);
    for (int d = 0; d < 3; ++d) v[d] = rel[d] + vc[d];
    return true;
  }

 private:
  FIRN_HD T body_distance(const T y[3], T n[3]) const {
    n[0] = n[1] = n[2] = T(0);
    switch (shape) {
      case ColliderShape::plane:
        n[1] = T(1);
        return y[1];
      case ColliderShape::box: {
        T q[3], outside2 = T(0), inside = -T(INFINITY);
        int face = 0;
        for (int d = 0; d < 3; ++d) {
          q[d] = std::fabs(y[d]) - half[d];
          n[d] = q[d] > T(0) ? (y[d] > T(0) ? q[d] : -q[d]) : T(0);
          outside2 += q[d] > T(0) ? q[d] * q[d] : T(0);
          if (q[d] > inside) inside = q[d], face = d;
        }
        if (outside2 > T(0)) {
          const T len = std::sqrt(outside2);
          for (int d = 0; d < 3; ++d) n[d] /= len;
          return len;
        }
        n[0] = n[1] = n[2] = T(0);
        n[face] = y[face] > T(0) ? T(1) : T(-1);
        return inside;
      }
      case ColliderShape::cylinder: {
        TireShape<T> plain;  // a tire without tread is a capped cylinder
        plain.radius = radius;
        plain.width = T(2) * half[2];
        plain.tread_depth = T(0);
        return plain.distance(y, n);
      }
      case ColliderShape::tire:
        return tire.distance(y, n);
    }
    return T(INFINITY);
  }
};

// The same collider in another precision (the engine keeps poses in double).
template <class T, class U>
Collider<T> collider_cast(const Collider<U>& c) {
  Collider<T> o;
  o.shape = c.shape;
  o.boundary = c.boundary;
  o.friction = Friction<T>{c.friction.law, T(c.friction.mu)};
  o.contact = c.contact;
  for (int i = 0; i < 3; ++i) {
    o.center[i] = T(c.center[i]);
    o.velocity[i] = T(c.velocity[i]);
    o.angular_velocity[i] = T(c.angular_velocity[i]);
    o.half[i] = T(c.half[i]);
  }
  for (int i = 0; i < 9; ++i) o.rotation[i] = T(c.rotation[i]);
  o.radius = T(c.radius);
  o.tire = tire_shape_cast<T>(c.tire);
  return o;
}

}  // namespace firn
