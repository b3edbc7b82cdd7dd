// The step's constitutive update over one material's particles [begin, begin + n), as the term of a
// parallel_reduce: the return mapping of a plastic model (projecting the previous G2P's trial F,
// written back only when it changed), then the Kirchhoff stress tau into the particle's columns.
// The summary names the first particle with a non-finite stress (where NaNs are born, before P2G
// spreads them) and the largest P-wave modulus K + 4G/3 (which sets the next time step).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "kernels/float_limits.hpp"
#include "kernels/hd.hpp"
#include "kernels/particle_state.hpp"

namespace firn {

struct ConstitutiveSummary {
  std::size_t first_bad = kNoParticle;
  double max_modulus = 0;
};

struct MergeConstitutive {
  FIRN_HD void operator()(ConstitutiveSummary& a, const ConstitutiveSummary& b) const {
    a.first_bad = std::min(a.first_bad, b.first_bad);
    a.max_modulus = std::max(a.max_modulus, b.max_modulus);
  }
};

template <class T, class Model>
struct ConstitutiveUpdate {
  ParticleView<T> pv;
  Model model;
  std::size_t begin;

  FIRN_HD void operator()(std::size_t i, ConstitutiveSummary& acc) const {
    const std::size_t p = begin + i;
    Mat3<T> F = particle_F(pv, p);
    PlasticState<T> state = particle_plastic_state(pv, p);
    if constexpr (Model::kPlastic) {
      if (model.project(F, state)) {
        for (int q = 0; q < 9; ++q) pv.F[q][p] = F.m[q];
        if constexpr (Model::kUsesAlpha) pv.alpha[p] = state.alpha;
        if constexpr (Model::kUsesJp) pv.Jp[p] = state.Jp;
      }
    }
    const Mat3<T> tau = model.kirchhoff(F, state);
    pv.tau[0][p] = tau(0, 0);
    pv.tau[1][p] = tau(1, 1);
    pv.tau[2][p] = tau(2, 2);
    pv.tau[3][p] = tau(0, 1);
    pv.tau[4][p] = tau(1, 2);
    pv.tau[5][p] = tau(2, 0);
    if (!std::isfinite(tau(0, 0) + tau(1, 1) + tau(2, 2) + tau(0, 1) + tau(1, 2) + tau(2, 0)) && p < acc.first_bad)
      acc.first_bad = p;
    acc.max_modulus = std::max(acc.max_modulus, double(model.p_wave_modulus(state)));
  }
};

}  // namespace firn
