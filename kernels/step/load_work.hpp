// The work of the body accelerations (loads, a tilted gravity) in one step, as the term of a
// parallel_reduce over particles: P2G kicks each particle's velocity by dt a before it scatters
// (kernels/p2g.hpp), which adds 1/2 m (|v + dt a|^2 - |v|^2) = m dt a . (v + dt a / 2) to its kinetic
// energy (issue 19, the energy budget).
#pragma once

#include <cstddef>

#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn {

template <class T>
struct LoadWork {
  ParticleView<T> pv;
  T dt;

  FIRN_HD void operator()(std::size_t p, double& acc) const {
    double w = 0;
    for (int d = 0; d < 3; ++d) {
      const double a = double(pv.body_accel[d][p]);
      w += a * (double(pv.v[d][p]) + 0.5 * double(dt) * a);
    }
    acc += double(pv.mass[p]) * double(dt) * w;
  }
};

}  // namespace firn
