// The diagnostics' sums over particles as the term of a parallel_reduce: kinetic energy
// sum 1/2 m |v|^2, momentum sum m v, the largest speed and the smallest total J = det(F_E F_P),
// accumulated in double whatever the precision.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "kernels/float_limits.hpp"
#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"
#include "kernels/particle_state.hpp"

namespace firn {

struct MotionSums {
  double ke = 0, p[3] = {0, 0, 0}, max_speed = 0, min_J = FloatLimits<double>::kMax;
};

template <class T>
struct MotionTerm {
  ParticleView<T> pv;

  FIRN_HD void operator()(std::size_t p, MotionSums& acc) const {
    const double m = pv.mass[p], v[3] = {pv.v[0][p], pv.v[1][p], pv.v[2][p]};
    const double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    acc.ke += 0.5 * m * v2;
    for (int d = 0; d < 3; ++d) acc.p[d] += m * v[d];
    acc.max_speed = std::max(acc.max_speed, std::sqrt(v2));
    acc.min_J = std::min(acc.min_J, double(particle_total_J(pv, p)));
  }
};

struct MergeMotionSums {
  FIRN_HD void operator()(MotionSums& a, const MotionSums& b) const {
    a.ke += b.ke;
    for (int d = 0; d < 3; ++d) a.p[d] += b.p[d];
    a.max_speed = std::max(a.max_speed, b.max_speed);
    a.min_J = std::min(a.min_J, b.min_J);
  }
};

}  // namespace firn
