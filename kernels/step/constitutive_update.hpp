// The step's constitutive update over one material's particles [begin, begin + n), as the term of a
// parallel_reduce: the return mapping of a plastic model (projecting the previous G2P's trial F,
// written back only when it changed), then the Kirchhoff stress tau into the particle's columns.
// The summary names the first particle with a non-finite stress (where NaNs are born, before P2G
// spreads them) and the largest P-wave modulus K + 4G/3 (which sets the next time step). With
// `plastic_work` set it also sums V0 times each return mapping's plastic work density, the work
// of the stress on the plastic strain increment, tau : d(eps_p) (dissipated or, with hardening,
// partly stored in the hardening variable), as the model defines it (Model::plastic_work; issue 19,
// the energy budget).
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
  double plastic_work = 0;  // J, when ConstitutiveUpdate::plastic_work is set
};

struct MergeConstitutive {
  FIRN_HD void operator()(ConstitutiveSummary& a, const ConstitutiveSummary& b) const {
    a.first_bad = std::min(a.first_bad, b.first_bad);
    a.max_modulus = std::max(a.max_modulus, b.max_modulus);
    a.plastic_work += b.plastic_work;
  }
};

// The return mapping of a plastic model, here and in the material driver
// (engine/verification/material_driver.cpp); when `work` is not null, the model's plastic work
// density of the return is added to *work. Returns whether F changed.
template <class T, class Model>
FIRN_HD bool project_measuring_work(const Model& model, Mat3<T>& F, PlasticState<T>& state, T* work) {
  const Mat3<T> F_trial = F;
  const PlasticState<T> before = state;
  if (!model.project(F, state)) return false;
  if (work) *work += model.plastic_work(F_trial, before, F, state);
  return true;
}

template <class T, class Model>
struct ConstitutiveUpdate {
  ParticleView<T> pv;
  Model model;
  std::size_t begin;
  bool plastic_work = false;

  FIRN_HD void operator()(std::size_t i, ConstitutiveSummary& acc) const {
    const std::size_t p = begin + i;
    Mat3<T> F = particle_F(pv, p);
    PlasticState<T> state = particle_plastic_state(pv, p);
    if constexpr (Model::kPlastic) {
      T work = T(0);
      if (project_measuring_work(model, F, state, plastic_work ? &work : nullptr)) {
        for (int q = 0; q < 9; ++q) pv.F[q][p] = F.m[q];
        if constexpr (Model::kUsesAlpha) pv.alpha[p] = state.alpha;
        if constexpr (Model::kUsesJp) pv.Jp[p] = state.Jp;
        acc.plastic_work += double(pv.vol0[p]) * double(work);
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
