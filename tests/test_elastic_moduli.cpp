// Conversions between E, nu, K and G (the thesis' Table 2.1).
#include <gtest/gtest.h>

#include <stdexcept>

#include "engine/elastic_moduli.hpp"

namespace firn {
namespace {

TEST(ElasticModuli, EveryPairRoundTrips) {
  const ElasticModuli ref = ElasticModuli::from_E_nu(1e5, 0.3);
  EXPECT_NEAR(ref.K, 1e5 / 1.2, 1e-9);
  EXPECT_NEAR(ref.G, 1e5 / 2.6, 1e-9);
  const ElasticModuli pairs[] = {
      ElasticModuli::from_any_two({}, {}, ref.K, ref.G),  ElasticModuli::from_any_two(ref.E, {}, ref.K, {}),
      ElasticModuli::from_any_two(ref.E, {}, {}, ref.G),  ElasticModuli::from_any_two({}, ref.nu, ref.K, {}),
      ElasticModuli::from_any_two({}, ref.nu, {}, ref.G),
  };
  for (const ElasticModuli& m : pairs) {
    EXPECT_NEAR(m.E, ref.E, 1e-9 * ref.E);
    EXPECT_NEAR(m.nu, ref.nu, 1e-12);
    EXPECT_NEAR(m.K, ref.K, 1e-9 * ref.K);
    EXPECT_NEAR(m.G, ref.G, 1e-9 * ref.G);
  }
}

TEST(ElasticModuli, ThesisHardSnow) {
  // Thesis Table 4.3 hard snow: K = 78 kPa, G = 58.3 kPa, i.e. Stomakhin's E0 = 1.4e5 Pa, nu = 0.2.
  const ElasticModuli m = ElasticModuli::from_any_two({}, {}, 78e3, 58.3e3);
  EXPECT_NEAR(m.E, 1.40015e5, 1);
  EXPECT_NEAR(m.nu, 0.2008, 1e-4);
  EXPECT_NEAR(m.lambda(), 78e3 - 2 * 58.3e3 / 3, 1e-9);
}

TEST(ElasticModuli, RejectsNonPhysical) {
  EXPECT_THROW(ElasticModuli::from_E_nu(1e5, 0.5), std::invalid_argument);
  EXPECT_THROW(ElasticModuli::from_E_nu(1e5, -1.0), std::invalid_argument);
  EXPECT_THROW(ElasticModuli::from_E_nu(-1e5, 0.3), std::invalid_argument);
  EXPECT_THROW(ElasticModuli::from_any_two(1.0, 0.3, 1.0, {}), std::invalid_argument);
  EXPECT_THROW(ElasticModuli::from_any_two(1.0, {}, {}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace firn
