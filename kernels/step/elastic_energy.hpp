// Stored elastic energy sum V0_p W(F_p) over one material's particles [begin, begin + n), as the
// term of a parallel_reduce (W the model's energy density per rest volume).
#pragma once

#include <cstddef>

#include "kernels/hd.hpp"
#include "kernels/particle_state.hpp"

namespace firn {

template <class T, class Model>
struct ElasticEnergy {
  ParticleView<T> pv;
  Model model;
  std::size_t begin;

  FIRN_HD void operator()(std::size_t i, double& acc) const {
    const std::size_t p = begin + i;
    acc += double(pv.vol0[p]) * double(model.energy_density(particle_F(pv, p), particle_plastic_state(pv, p)));
  }
};

}  // namespace firn
