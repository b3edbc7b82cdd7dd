#include "engine/elastic_moduli.hpp"

#include <stdexcept>
#include <string>

namespace firn {

ElasticModuli ElasticModuli::from_any_two(std::optional<double> E, std::optional<double> nu, std::optional<double> K,
                                          std::optional<double> G) {
  const int given = int(E.has_value()) + int(nu.has_value()) + int(K.has_value()) + int(G.has_value());
  if (given != 2)
    throw std::invalid_argument("exactly two of E, nu, K, G must be given (got " + std::to_string(given) + ")");
  ElasticModuli m{};
  if (E && nu) {
    m = {*E, *nu, *E / (3 * (1 - 2 * *nu)), *E / (2 * (1 + *nu))};
  } else if (K && G) {
    m = {9 * *K * *G / (3 * *K + *G), (3 * *K - 2 * *G) / (2 * (3 * *K + *G)), *K, *G};
  } else if (E && K) {
    m = {*E, (3 * *K - *E) / (6 * *K), *K, 3 * *K * *E / (9 * *K - *E)};
  } else if (E && G) {
    m = {*E, *E / (2 * *G) - 1, *E * *G / (3 * (3 * *G - *E)), *G};
  } else if (K && nu) {
    m = {3 * *K * (1 - 2 * *nu), *nu, *K, 3 * *K * (1 - 2 * *nu) / (2 * (1 + *nu))};
  } else {  // G && nu
    m = {2 * *G * (1 + *nu), *nu, 2 * *G * (1 + *nu) / (3 * (1 - 2 * *nu)), *G};
  }
  if (!(m.nu > -1.0 && m.nu < 0.5))
    throw std::invalid_argument("Poisson's ratio " + std::to_string(m.nu) + " is outside (-1, 0.5)");
  if (!(m.E > 0 && m.K > 0 && m.G > 0))
    throw std::invalid_argument("moduli must be positive (E = " + std::to_string(m.E) + ", K = " + std::to_string(m.K) +
                                ", G = " + std::to_string(m.G) + ")");
  return m;
}

}  // namespace firn
