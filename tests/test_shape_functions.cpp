// Quadratic and cubic B-spline weights: partition of unity, zero first moment and the second
// moment 1 / kDinv in grid units, which is why D^-1 = kDinv / dx^2 (Jiang et al. 2015, Sec. 5.3).
#include <gtest/gtest.h>

#include "kernels/shape_functions.hpp"

namespace firn {
namespace {

template <class ShapeT>
void check_moments() {
  constexpr int S = ShapeT::kSupport;
  for (int i = 0; i <= 100; ++i) {
    const double X = 10 + ShapeT::kOffset + i / 100.0 * 0.999999;
    const int base = ShapeT::base(X);
    const double f = X - base;
    double w[S];
    ShapeT::weights(f, w);
    double sum = 0, first = 0, second = 0;
    for (int a = 0; a < S; ++a) {
      EXPECT_GE(w[a], 0.0);
      sum += w[a];
      first += w[a] * (a - f);
      second += w[a] * (a - f) * (a - f);
    }
    EXPECT_NEAR(sum, 1.0, 1e-14) << "f = " << f;
    EXPECT_NEAR(first, 0.0, 1e-14) << "f = " << f;
    EXPECT_NEAR(second, 1.0 / ShapeT::kDinv, 1e-14) << "f = " << f;
  }
}

TEST(ShapeFunctions, QuadraticMoments) { check_moments<QuadraticBSpline<double>>(); }
TEST(ShapeFunctions, CubicMoments) { check_moments<CubicBSpline<double>>(); }

TEST(ShapeFunctions, KnownValues) {
  double w[4];
  QuadraticBSpline<double>::weights(1.0, w);  // particle on a node: 1/8, 3/4, 1/8
  EXPECT_DOUBLE_EQ(w[0], 0.125);
  EXPECT_DOUBLE_EQ(w[1], 0.75);
  EXPECT_DOUBLE_EQ(w[2], 0.125);
  CubicBSpline<double>::weights(1.0, w);  // on a node: 1/6, 2/3, 1/6, 0
  EXPECT_NEAR(w[0], 1.0 / 6, 1e-15);
  EXPECT_NEAR(w[1], 2.0 / 3, 1e-15);
  EXPECT_NEAR(w[2], 1.0 / 6, 1e-15);
  EXPECT_NEAR(w[3], 0.0, 1e-15);
}

}  // namespace
}  // namespace firn
