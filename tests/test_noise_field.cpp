// The noise field of heterogeneous materials (engine/noise_field.hpp): deterministic for a seed,
// within [-1, 1] with mean 0, smooth, and with the correlation length `scale`.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/noise_field.hpp"
#include "engine/splitmix64.hpp"

namespace firn {
namespace {

using Point = std::array<double, 3>;

std::vector<Point> random_points(std::size_t count, double extent, std::uint64_t seed) {
  SplitMix64 rng{seed};
  std::vector<Point> points(count);
  for (Point& p : points)
    for (double& c : p) c = extent * (2 * rng.uniform() - 1);
  return points;
}

// Mean |n(x) - n(x + d)| over random points and the three axis directions.
double mean_increment(const NoiseField& n, double d) {
  double sum = 0;
  const std::vector<Point> points = random_points(20000, 1.0, 7);
  for (const Point& x : points)
    for (int axis = 0; axis < 3; ++axis) {
      Point y = x;
      y[axis] += d;
      sum += std::fabs(n(x) - n(y));
    }
  return sum / double(3 * points.size());
}

TEST(NoiseField, SameSeedSameValuesOtherSeedOthers) {
  const NoiseField a(0.015, 1), b(0.015, 1), c(0.015, 2);
  int differ = 0;
  for (const Point& x : random_points(1000, 0.5, 3)) {
    EXPECT_EQ(a(x), b(x));  // bit for bit
    differ += a(x) != c(x);
  }
  EXPECT_GT(differ, 990);
}

TEST(NoiseField, WithinMinusOneToOneWithMeanZero) {
  const NoiseField n(0.015, 1);
  double lo = 1, hi = -1, sum = 0, sum2 = 0;
  const std::vector<Point> points = random_points(200000, 2.0, 5);
  for (const Point& x : points) {
    const double v = n(x);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / double(points.size()), sd = std::sqrt(sum2 / double(points.size()) - mean * mean);
  EXPECT_GE(lo, -1.0);
  EXPECT_LE(hi, 1.0);
  EXPECT_LT(lo, -0.8);  // it uses its range
  EXPECT_GT(hi, 0.8);
  EXPECT_NEAR(mean, 0, 0.01);
  EXPECT_NEAR(sd, 0.4, 0.03);  // the value the scene reference quotes
}

// At node spacing `scale`: nearby points agree, points a few scales apart are independent.
TEST(NoiseField, CorrelationLengthFollowsScale) {
  const double scale = 0.015;
  const NoiseField n(scale, 1);
  const double near = mean_increment(n, scale / 50), far = mean_increment(n, 4 * scale);
  EXPECT_LT(near, 0.05 * far) << near << " " << far;
  EXPECT_GT(far, 0.35);  // E|a - b| of independent normal values with sd 0.4 is 0.45
  // The field of scale 2s at 2x is the field of scale s at x, bit for bit: every length in it,
  // the correlation length among them, is proportional to `scale`.
  const NoiseField wide(2 * scale, 1);
  for (const Point& x : random_points(1000, 0.5, 9)) EXPECT_EQ(wide({2 * x[0], 2 * x[1], 2 * x[2]}), n(x));
}

TEST(NoiseField, IsContinuousAcrossLatticeCells) {
  const NoiseField n(0.01, 4);
  for (int i = -50; i <= 50; ++i) {
    const double node = 0.01 * i;  // a lattice plane: both sides must agree
    EXPECT_NEAR(n({node - 1e-12, 0.0031, -0.0047}), n({node + 1e-12, 0.0031, -0.0047}), 1e-9);
  }
}

}  // namespace
}  // namespace firn
