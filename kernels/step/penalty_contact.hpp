// Penalty contact of a rigid collider at the particles (`contact = "penalty"`; issue 19, docs/contact.md
// "A penalty contact at the particles"). Node contact sets the velocity of every grid node inside
// the collider at each step, and that projection dissipates per step: the towed frictionless tire
// over an elastic bed, whose continuum resistance is zero, meets more resistance the smaller the
// time step. Here the collider leaves the grid alone and pushes the particles that overlap it with a
// force of a spring of their own mass: a penalty method (Wriggers, Computational Contact Mechanics,
// 2nd ed., 2006), evaluated at the material points against the collider's signed distance, as the
// particle-to-boundary contacts of MPM do with a penalty (arXiv:2403.13534, "A high-fidelity material
// point method for frictional contact problems") or a barrier (Li, Fang, Li and Jiang 2022, CMAME
// 390, "BFEMP: interpenetration-free MPM-FEM coupling with barrier contact"):
//   particle p a ball of radius r_p = V0_p^(1/3) / 2 (half its rest spacing), gap g = d(x_p) - r_p
//   with d the collider's signed distance and n its outward normal; where g < 0,
//     a_p = omega^2 (-g) n,  potential m_p omega^2 g^2 / 2,
// applied as a kick before P2G with the particle's position at the step's start (symplectic Euler:
// v += dt a(x_n), then the transfers move x with the new velocity), so the contact stores the
// energy it takes and gives it back as the particle leaves. The engine sets omega = k c / dx, c the
// fastest material's P-wave speed at rest and k the collider's `penalty_stiffness`: the overlap that carries a
// pressure p is then about p dx^2 / (rho c^2 k^2 h) for a particle spacing h = 2 r_p (a strain of
// the material times a fraction of a cell), and omega dt <= k cfl c / (c_step + |v|) <= k cfl (the
// step's wave speed c_step is at least about c) keeps the explicit spring stable, omega dt < 2; the
// engine refuses a step with omega dt above kPenaltyStableOmegaDt, the scene reader a
// penalty_stiffness cfl that reaches it.
// Friction acts on the impulse (Coulomb's |J_t| <= mu |J_n|): after the normal kick, the velocity
// relative to the collider's surface, v_c(x_p) = v + omega_c x (x_p - c), keeps its normal part and
// loses at most mu(|v_t|) dt |a_p| of its tangential speed |v_t| (kernels/friction.hpp), never
// reversing it. The collider is unilateral (boundary "separate"): it only ever pushes.
// Sums, as the term of a parallel_reduce: the force on the collider, -sum m dv / dt, its torque about
// the collider's centre, and the collider's work on the material, sum m dv . v_c(x_p) (the node
// contact's, grid_update.hpp, at the particles).
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/colliders.hpp"
#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"
#include "kernels/step/collider_sums.hpp"

namespace firn {

enum PenaltySum : int { kPenaltyForce = 0, kPenaltyTorque = 3, kPenaltyWork = 6, kPenaltySums = 7 };

// The largest omega dt the engine runs: the symplectic Euler spring is stable below 2.
constexpr double kPenaltyStableOmegaDt = 1.9;

template <class T>
struct PenaltyContact {
  ParticleView<T> pv;
  Collider<T> collider;  // posed at the step's start
  T lo[3], hi[3];        // the collider's box widened by the largest particle radius
  T omega2;              // omega^2 (1/s^2)
  T dt;

  FIRN_HD void operator()(std::size_t p, DoubleSums<kPenaltySums>& acc) const {
    const T x[3] = {pv.x[0][p], pv.x[1][p], pv.x[2][p]};
    for (int d = 0; d < 3; ++d)
      if (!(x[d] >= lo[d] && x[d] <= hi[d])) return;  // no overlap possible
    T n[3];
    const T gap = collider.distance(x, n) - T(0.5) * std::cbrt(pv.vol0[p]);
    if (!(gap < T(0))) return;
    T vc[3], rel[3];
    collider.velocity_at(x, vc);
    const T push = dt * omega2 * (-gap);  // the normal speed change
    for (int d = 0; d < 3; ++d) rel[d] = pv.v[d][p] - vc[d] + push * n[d];
    const T vn = rel[0] * n[0] + rel[1] * n[1] + rel[2] * n[2];
    T vt[3] = {rel[0] - vn * n[0], rel[1] - vn * n[1], rel[2] - vn * n[2]};
    const T slip = std::sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]);
    if (collider.friction.mu > T(0) && slip > T(0)) {
      const T keep = collider.friction.slip_kept(slip, push);
      for (int d = 0; d < 3; ++d) vt[d] *= keep;
    }
    const double m = double(pv.mass[p]);
    double f[3];
    for (int d = 0; d < 3; ++d) {
      const T v = vc[d] + vn * n[d] + vt[d];
      const double dv = double(v) - double(pv.v[d][p]);
      pv.v[d][p] = v;
      f[d] = -m * dv / double(dt);
      acc.v[kPenaltyForce + d] += f[d];
      acc.v[kPenaltyWork] += m * dv * double(vc[d]);
    }
    const double r[3] = {double(x[0] - collider.center[0]), double(x[1] - collider.center[1]),
                         double(x[2] - collider.center[2])};
    acc.v[kPenaltyTorque + 0] += r[1] * f[2] - r[2] * f[1];
    acc.v[kPenaltyTorque + 1] += r[2] * f[0] - r[0] * f[2];
    acc.v[kPenaltyTorque + 2] += r[0] * f[1] - r[1] * f[0];
  }
};

}  // namespace firn
