// Pooled collider contact (`[[colliders]] contact = "pooled"`; issue 19, item 2; docs/contact.md,
// attempt G): the contact of one stiff body with a collider, taken as a whole.
//
// The node-by-node condition (kernels/colliders.hpp) clamps every approaching node inside the
// collider. Under a body resting or rolling on it, the nodes that carry load form a row about
// sqrt(3 R dx) wide, much wider than the elastic contact, over which a turning body's extrapolated
// normal velocity is linear, a + omega x; clamped node by node, only the nodes ahead take an
// impulse, which puts the normal force ahead of the centre (a numerical rolling resistance of
// 0.03-0.06 R at R/dx = 10, and a rolling error that does not converge). The pooled condition
// instead gives every node inside the collider (signed distance below -skin) the same normal
// velocity change, lambda, so that the impulse is spread by mass and the body's rotation across
// the contact is left alone, with one guard per node: no node may carry its material (x̄_i, the
// mass-weighted particle position at the node) across the surface this step. So node i takes
//   dv_n,i = max(lambda, least_i),  least_i = -v_n,i - max(0, g_i) / dt,
// with g_i = d(x̄_i) + dt v_c . n the gap at the step's start (d is measured at the collider's pose
// at the step's end), and lambda >= 0 is the smallest value for which the contact does not
// approach on mass average,
//   S(lambda) = sum_i m_i (v_n,i + max(lambda, least_i)) >= 0.
// This is the least kinetic-energy change (sum m dv^2) that satisfies both constraints (the
// pooled one and every node's guard): its optimality conditions give dv_i = lambda + its own
// guard's multiplier. S is convex, piecewise linear and increasing, and Newton's method from
// lambda_0 = -(sum m v_n) / (sum m) (where S >= 0) descends to its root from above, every iterate
// feasible (engine: Simulation::solve_contact_pool). Where the guard holds no node (the usual
// case for a stiff body), lambda_0 is the root.
//
// The friction acts on the surface row alone: the nodes outside the collider by less than half a
// cell (-skin <= d < dx/2), whose tangential velocity is what the lowest particles feel; the nodes
// inside keep theirs, so nothing sticks one cell inside the collider (where a rolling body's
// extrapolated velocity moves backward at omega dx). Coulomb's bound is applied to the contact's
// resultant rather than node by node (as in the nonlocal friction of Oden and Pires 1983, J. Appl.
// Mech. 50:67-76, where the normal stress that bounds the friction is averaged over a
// neighbourhood; here the neighbourhood is the pool): the capacity mu sum m dv_n of the inside nodes,
// mu taken at the surface row's mean slip, against the demand sum m |v_t| of the surface row, which
// then sticks whole or slides with exactly mu times the pool's normal impulse (the share
// `keep` = 1 - capacity / demand of its slip).
//
// For a stiff body whose contact with the collider is one patch: on the incline problems of
// `firn verify` the rolling error falls with resolution and the sliding one stays within 0.15%
// (docs/contact.md, attempt G). It is not a law for snow, or for several bodies on one collider:
// the pool would let the material ahead of a tread approach while the material behind leaves, held
// back only by the guard. Keep its contact out of the bands of sticky walls and of walls facing
// along its normal: a wall acting after it would undo part of the pool's change.
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/colliders.hpp"
#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"

namespace firn {

enum PoolRole : signed char { kPoolNone, kPoolSurface, kPoolInside };

// One node's relation to a pooled collider.
template <class T>
struct PoolNode {
  signed char role = kPoolNone;
  T n[3];       // outward normal
  T vc[3];      // the collider's velocity at the node
  T vn;         // normal velocity relative to the collider
  T least;      // inside nodes: the guard's least normal velocity change, least_i above
};

// The node at x with velocity v and mass m; `moment` points at its mass moment
// sum_p m_p w_ip (x_p - x_i) / dx, one value per axis kBlockNodes apart (the first three channels
// of kernels/step/contact_normals.hpp with one contact group).
template <class T>
FIRN_HD PoolNode<T> pool_node(const Collider<T>& k, const T x[3], const T v[3], T m, const T* moment, T dx, T skin,
                              T dt) {
  PoolNode<T> q;
  const T d = k.distance(x, q.n);
  if (!(d < T(0.5) * dx)) return q;
  q.role = d < -skin ? kPoolInside : kPoolSurface;
  k.velocity_at(x, q.vc);
  q.vn = T(0);
  for (int i = 0; i < 3; ++i) q.vn += (v[i] - q.vc[i]) * q.n[i];
  q.least = T(0);
  if (q.role == kPoolInside) {
    T xm[3], nm[3];  // x̄_i
    for (int i = 0; i < 3; ++i) xm[i] = x[i] + moment[i * kBlockNodes] / m * dx;
    // The gap at the start of the step: the collider is posed at the step's end, and its surface
    // moved v_c . n dt along the normal meanwhile.
    T gap = k.distance(xm, nm);
    for (int i = 0; i < 3; ++i) gap += dt * q.vc[i] * q.n[i];
    q.least = -q.vn - (gap > T(0) ? gap : T(0)) / dt;
  }
  return q;
}

// The node's normal velocity change for the pool's lambda.
template <class T>
FIRN_HD T pool_normal_change(const PoolNode<T>& q, T lambda) {
  return q.least > lambda ? q.least : lambda;
}

// The node's tangential velocity relative to the collider, and its magnitude.
template <class T>
FIRN_HD T pool_tangential(const PoolNode<T>& q, const T v[3], T t[3]) {
  T t2 = T(0);
  for (int i = 0; i < 3; ++i) {
    t[i] = v[i] - q.vc[i] - q.vn * q.n[i];
    t2 += t[i] * t[i];
  }
  return std::sqrt(t2);
}

// The node's velocity after the pool: v <- v_c + (v_n + dv_n) n + scale t, with t the tangential
// velocity relative to the collider; inside nodes take dv_n = max(lambda, least) and keep t
// (scale 1), the surface row takes no normal change and keeps the share `keep` of its slip.
template <class T>
FIRN_HD void apply_pool(const PoolNode<T>& q, T lambda, T keep, T v[3]) {
  T t[3];
  pool_tangential(q, v, t);
  const bool inside = q.role == kPoolInside;
  const T dvn = inside ? pool_normal_change(q, lambda) : T(0), scale = inside ? T(1) : keep;
  for (int i = 0; i < 3; ++i) v[i] = q.vc[i] + (q.vn + dvn) * q.n[i] + scale * t[i];
}

}  // namespace firn
