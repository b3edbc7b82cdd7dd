// The pooled collider's lambda and friction share (kernels/pooled_contact.hpp) from its sums over the
// grid (kernels/step/contact_pool_sums.hpp); engine: Simulation::solve_contact_pool.
//
// lambda is the smallest value >= 0 with S(lambda) >= 0, found by Newton's method on the convex,
// piecewise linear, increasing S from lambda_0 = -(sum m v_n) / (sum m), where S >= 0 (each node
// takes at least lambda_0, so the pool does not approach on average). Each Newton step from a point
// where S >= 0 lands at or above the root, so every iterate is feasible and stopping early keeps the
// contact from approaching. Two ends:
// - S' = 0: every inside node is held by its guard at this lambda, and at any lambda below it, so
//   they take max(0, least_i) = least_i whatever lambda; lambda = 0 says so.
// - A step below 0 (S(0) > 0: the nodes that leave outweigh the approach that is left once the
//   guarded nodes are held): lambda = 0, evaluated once more for the friction, then done.
// Then Coulomb's bound on the whole contact: the surface row keeps the share 1 - capacity / demand
// of its slip, or none (it sticks), with capacity mu times the pool's normal impulse and mu at the
// row's mean slip.
#pragma once

#include <algorithm>

#include "kernels/step/contact_pool_sums.hpp"

namespace firn {

struct PoolSolution {
  double lambda = 0;  // the inside nodes' common normal velocity change
  double keep = 0;    // the share of its slip the surface row keeps
  int evaluations = 0;  // of the sums
};

// Newton's steps are few: the guard holds a few nodes at most, and each step passes a breakpoint.
constexpr int kPoolNewtonSteps = 8;
constexpr double kPoolTolerance = 1e-6;  // of lambda, on the mean normal velocity

// `sums(lambda)` returns the DoubleSums<kPoolSums> of kernels/step/contact_pool_sums.hpp;
// `coefficient(slip)` the friction coefficient at a slip speed.
template <class Sums, class Coefficient>
PoolSolution solve_pool(const Sums& sums, const Coefficient& coefficient) {
  PoolSolution r;
  DoubleSums<kPoolSums> s = sums(0.0);
  r.evaluations = 1;
  const double mass = s.v[0];
  if (mass > 0 && s.v[1] < 0) {  // the contact approaches on average
    double lambda = -s.v[1] / mass;
    for (int i = 0;; ++i) {
      s = sums(lambda);
      ++r.evaluations;
      if (!(s.v[3] > 0)) {
        lambda = 0;
        break;
      }
      if (s.v[2] <= kPoolTolerance * lambda * mass || lambda == 0 || i == kPoolNewtonSteps) break;
      lambda = std::max(0.0, lambda - s.v[2] / s.v[3]);  // at 0: evaluated once more, then done
    }
    r.lambda = lambda;
  }
  const double demand = s.v[5], slip = s.v[6] > 0 ? demand / s.v[6] : 0.0;
  const double capacity = coefficient(slip) * s.v[4];
  r.keep = demand > capacity ? 1 - capacity / demand : 0;
  return r;
}

}  // namespace firn
