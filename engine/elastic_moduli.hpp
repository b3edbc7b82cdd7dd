// Isotropic elastic moduli from any two of Young's modulus E, Poisson's ratio nu, bulk modulus K
// and shear modulus G (the thesis' Table 2.1; standard conversion formulas). Lame's lambda and
// mu = G follow. Throws std::invalid_argument for a non-physical combination.
#pragma once

#include <optional>

namespace firn {

struct ElasticModuli {
  double E, nu, K, G;
  double lambda() const { return K - 2.0 * G / 3.0; }
  double mu() const { return G; }
  // P-wave modulus K + 4G/3, which sets the time step (DESIGN.md section 3).
  double p_wave() const { return K + 4.0 * G / 3.0; }

  static ElasticModuli from_any_two(std::optional<double> E, std::optional<double> nu, std::optional<double> K,
                                    std::optional<double> G);
  static ElasticModuli from_E_nu(double E, double nu) { return from_any_two(E, nu, {}, {}); }
};

}  // namespace firn
