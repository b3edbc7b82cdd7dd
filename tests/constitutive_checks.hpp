// Checks shared by the constitutive-model tests.
#pragma once

#include <gtest/gtest.h>

#include "kernels/constitutive/plastic_state.hpp"
#include "kernels/mat3.hpp"

namespace firn {

// tau = (dW/dF) F^T, with dW/dF from central differences (step h) of energy_density at the given
// plastic state, each component within 1e-5 of `scale` (a modulus of the model).
template <class Model>
void expect_stress_is_energy_derivative(const Model& model, const Mat3<double>& F, double scale,
                                        const PlasticState<double>& state = {}, double h = 1e-6) {
  Mat3<double> P;
  for (int q = 0; q < 9; ++q) {
    Mat3<double> Fp = F, Fm = F;
    Fp.m[q] += h;
    Fm.m[q] -= h;
    P.m[q] = (model.energy_density(Fp, state) - model.energy_density(Fm, state)) / (2 * h);
  }
  const Mat3<double> expected = mul_transposed(P, F);
  const Mat3<double> tau = model.kirchhoff(F, state);
  for (int q = 0; q < 9; ++q) EXPECT_NEAR(tau.m[q], expected.m[q], 1e-5 * scale) << "component " << q;
}

}  // namespace firn
