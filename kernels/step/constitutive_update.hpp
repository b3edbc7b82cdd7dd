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
#include "kernels/lanes.hpp"
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

// Whether a model has the lane form of its stress or, for a plastic model, of its return and the
// stress after it (Model::kLanes, with kirchhoff_lanes, or project_lanes where kPlastic), for
// ConstitutiveUpdateLanes.
template <class Model, class = void>
struct HasLanes : std::false_type {};
template <class Model>
struct HasLanes<Model, std::void_t<decltype(Model::kLanes)>> : std::integral_constant<bool, Model::kLanes> {};

// ConstitutiveUpdate on batches of W particles (kernels/lanes.hpp; issue 15): item `batch` covers
// particles [batch W, batch W + W) of the range, the last batch padded with copies of its first
// particle whose results are dropped. The lanes carry F and, for a plastic model, its one plastic
// scalar (alpha for J2 plasticity, J_P for Cam-clay snow) and run the model's lane form; a lane the
// lane form leaves to the scalar path (ok cleared) is updated by ConstitutiveUpdate itself. A
// plastic model's lane form gives the stress with the return (HyperelasticPlastic's from what the
// return holds); an elastic model's lane form is its stress alone. Every particle's result depends on its own state
// only, so it is the same for any batching and thread count.
template <class T, class Model, int W>
struct ConstitutiveUpdateLanes {
  static_assert(!Model::kPlastic || Model::kUsesAlpha != Model::kUsesJp,
                "a plastic model's lanes carry F and one plastic scalar");
  ConstitutiveUpdate<T, Model> one;
  std::size_t n;  // particles in the range

  static std::size_t batches(std::size_t particles) { return (particles + W - 1) / W; }

  FIRN_FLATTEN FIRN_HD void operator()(std::size_t batch, ConstitutiveSummary& acc) const {
    using L = Lanes<T, W>;
    const ParticleView<T>& pv = one.pv;
    T* const state = Model::kUsesAlpha ? pv.alpha : pv.Jp;
    const std::size_t first = one.begin + batch * W;
    const int count = n - batch * W < std::size_t(W) ? int(n - batch * W) : W;
    Mat3<L> F;
    L s, work(T(0));
    if (count == W) {  // contiguous loads
      for (int q = 0; q < 9; ++q) {
        FIRN_LANES
        for (int l = 0; l < W; ++l) F.m[q].v[l] = pv.F[q][first + l];
      }
      if constexpr (Model::kPlastic) {
        FIRN_LANES
        for (int l = 0; l < W; ++l) s.v[l] = state[first + l];
      }
    } else {
      for (int l = 0; l < W; ++l) {
        const std::size_t p = first + (l < count ? l : 0);
        for (int q = 0; q < 9; ++q) F.m[q].v[l] = pv.F[q][p];
        if constexpr (Model::kPlastic) s.v[l] = state[p];
      }
    }
    LaneMask<W> ok = LaneMask<W>::all(), plastic = LaneMask<W>::none();
    L tau[6];  // in ParticleView::tau's order
    if constexpr (Model::kPlastic)
      plastic = one.model.project_lanes(F, s, work, ok, tau);
    else
      one.model.kirchhoff_lanes(F, tau);
    // Where a lane yielded, every lane's F and plastic scalar are stored, changed or not (a lane that
    // did not yield, or that the lane form handed back, holds the values it read); where none did,
    // nothing changed and nothing is stored, which spares the columns' write-back. Then the stress.
    if (Model::kPlastic && any(plastic)) {
      for (int q = 0; q < 9; ++q) store_lanes(pv.F[q] + first, F.m[q], count);
      store_lanes(state + first, s, count);
    }
    for (int c = 0; c < 6; ++c) store_lanes(pv.tau[c] + first, tau[c], count);
    // The summary of the lanes the lane form returned (`counted`), in registers: the plastic work
    // summed in lane order and the first non-finite stress, each by a loop over the lanes only where
    // a lane has one, and the largest modulus as a float maximum (its double is the maximum of the
    // lanes' doubles). Then the lanes handed back, in lane order, each by the scalar update from the
    // F and state stored above: the values it read. (issue 15: a loop over every lane for all three
    // took 19 of neo-Hookean's 69 instructions per particle.)
    LaneMask<W> counted;
    for (int l = 0; l < W; ++l) counted.m[l] = ok.m[l] & int(l < count);
    ConstitutiveSummary sum = acc;
    const LaneMask<W> yielded = plastic && counted;
    if (one.plastic_work && any(yielded))
      for (int l = 0; l < count; ++l)
        if (yielded.m[l]) sum.plastic_work += double(pv.vol0[first + l]) * double(work.v[l]);
    const LaneMask<W> bad = counted && !finite(tau[0] + tau[1] + tau[2] + tau[3] + tau[4] + tau[5]);
    if (any(bad))
      for (int l = 0; l < count; ++l)
        if (bad.m[l]) sum.first_bad = std::min(sum.first_bad, first + l);
    // The largest modulus of the counted lanes, 0 where none is positive (a NaN is passed over): each
    // lane's, 0 where it is not counted or not positive, then their largest.
    L moduli;
    for (int l = 0; l < W; ++l) {
      const PlasticState<T> after = Model::kUsesAlpha ? PlasticState<T>{s.v[l], T(1)}
                                    : Model::kUsesJp  ? PlasticState<T>{T(0), s.v[l]}
                                                      : PlasticState<T>{};
      const T modulus = one.model.p_wave_modulus(after);
      moduli.v[l] = counted.m[l] && modulus > T(0) ? modulus : T(0);
    }
    sum.max_modulus = std::max(sum.max_modulus, double(largest(moduli)));
    acc = sum;
    for (int l = 0; l < count; ++l)
      if (!ok.m[l]) one(first + l - one.begin, acc);
  }
};

}  // namespace firn
