// A particle's deformation gradient, plastic state and total J, loaded from the structure-of-arrays columns
// into the small value types the constitutive models take.
#pragma once

#include <cstddef>

#include "kernels/constitutive/plastic_state.hpp"
#include "kernels/hd.hpp"
#include "kernels/mat3.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn {

template <class T>
FIRN_HD Mat3<T> particle_F(const ParticleView<T>& pv, std::size_t p) {
  Mat3<T> F;
  for (int q = 0; q < 9; ++q) F.m[q] = pv.F[q][p];
  return F;
}

// The fields the material keeps (alpha, Jp); the others at their defaults.
template <class T>
FIRN_HD PlasticState<T> particle_plastic_state(const ParticleView<T>& pv, std::size_t p) {
  PlasticState<T> s;
  if (pv.alpha) s.alpha = pv.alpha[p];
  if (pv.Jp) s.Jp = pv.Jp[p];
  return s;
}

// det of the whole deformation gradient F_E F_P of particle p.
template <class T>
FIRN_HD T particle_total_J(const ParticleView<T>& pv, std::size_t p) {
  const T J = determinant(particle_F(pv, p));
  return pv.Jp ? J * pv.Jp[p] : J;
}

}  // namespace firn
