// The work of the body accelerations (loads, an inflation pressure, a tilted gravity) in one step,
// as the term of a parallel_reduce over particles, taken twice per step: with the velocities at
// the step's start and again with those at its end, each time half of m dt a . v. Their sum,
// m dt a . (v_n + v_n+1) / 2, is the force times the step's mean velocity (the trapezoid rule in
// time). In free flight, where v_n+1 = v_n + dt a, it is the kick's exact kinetic energy,
// 1/2 m (|v_n + dt a|^2 - |v_n|^2); on a body held at rest by its stress it is zero, where the
// kick's energy alone, m dt a . (v_n + dt a / 2), would count m dt^2 |a|^2 / 2 of work every step
// that the stress then takes back (issue 19, the energy budget).
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
    for (int d = 0; d < 3; ++d) w += double(pv.body_accel[d][p]) * double(pv.v[d][p]);
    acc += 0.5 * double(pv.mass[p]) * double(dt) * w;
  }
};

}  // namespace firn
