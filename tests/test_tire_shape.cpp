// The tire's signed distance (kernels/tire_shape.hpp) and the thesis' tread patterns
// (engine/tread_patterns.cpp): exact sign, bounded distance error, unit normals, the patterns'
// defining properties.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "engine/tread_patterns.hpp"
#include "kernels/tire_shape.hpp"

namespace firn {
namespace {

constexpr double kPi = 3.141592653589793;
const char* kTreads[] = {"angled_footstep", "bowtie", "six_rib"};

TireShape<double> tire(const char* tread) { return make_tire_shape(tread, 0.2, 0.125, 0.012, 12); }

// Membership decided independently of the distance: cylindrical coordinates, the pitch fraction u
// and width fraction w, and the even-odd rule on each block in (u, w).
bool inside_tire(const TireShape<double>& t, const double y[3]) {
  const double r = std::hypot(y[0], y[1]);
  if (std::fabs(y[2]) > 0.5 * t.width || r > t.radius) return false;
  if (r <= t.radius - t.tread_depth) return true;
  double phi = std::atan2(y[1], y[0]);
  if (phi < 0) phi += 2 * kPi;
  const double u = std::fmod(phi * t.pitches / (2 * kPi), 1.0), w = y[2] / t.width;
  for (int b = 0; b < t.block_count; ++b)
    for (int shift = -1; shift <= 1; ++shift) {
      const TreadBlock<double>& k = t.blocks[b];
      bool in = false;
      for (int i = 0, j = k.vertex_count - 1; i < k.vertex_count; j = i++) {
        const double ui = k.u[i] + shift, uj = k.u[j] + shift;
        if ((k.w[i] > w) != (k.w[j] > w) && u < uj + (w - k.w[j]) * (ui - uj) / (k.w[i] - k.w[j])) in = !in;
      }
      if (in) return true;
    }
  return false;
}

// Points near the tread band, where the distance matters.
std::vector<std::array<double, 3>> samples(std::uint32_t seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> phi(0, 2 * kPi), r(0.17, 0.215), z(-0.075, 0.075);
  std::vector<std::array<double, 3>> p;
  for (int i = 0; i < count; ++i) {
    const double a = phi(rng), rr = r(rng);
    p.push_back({rr * std::cos(a), rr * std::sin(a), z(rng)});
  }
  return p;
}

TEST(TireShape, SignMatchesMembershipAndNormalsAreUnit) {
  for (const char* tread : kTreads) {
    const TireShape<double> t = tire(tread);
    int inside = 0;
    for (const auto& p : samples(7, 20000)) {
      double n[3];
      const double d = t.distance(p.data(), n);
      ASSERT_EQ(d <= 0, inside_tire(t, p.data())) << tread << " at " << p[0] << ", " << p[1] << ", " << p[2];
      ASSERT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1, 1e-9);
      inside += d <= 0;
    }
    EXPECT_GT(inside, 2000) << tread;
  }
}

// The distance skips blocks whose bounding box lies beyond the best distance so far; that must
// never change the answer. The tire's distance is the least of the carcass's and each block's, so
// it must equal, bit for bit, the least over tires that carry one block each (where only the
// carcass can make a block be skipped), in float (the engine's precision) and double.
template <class T>
void expect_skipping_changes_nothing() {
  for (const char* tread : kTreads) {
    const TireShape<T> t = tire_shape_cast<T>(tire(tread));
    for (const auto& p : samples(13, 20000)) {
      const T y[3] = {T(p[0]), T(p[1]), T(p[2])};
      T n[3];
      T least = T(INFINITY);
      for (int b = 0; b < t.block_count; ++b) {
        TireShape<T> one = t;
        one.block_count = 1;
        one.blocks[0] = t.blocks[b];
        least = std::min(least, one.distance(y, n));
      }
      ASSERT_EQ(t.distance(y, n), least) << tread << " at " << p[0] << ", " << p[1] << ", " << p[2];
    }
  }
}

// A slick tire with rounded shoulders is the square one shrunk by s and grown by a ball of radius s:
// beside the rounded edge the distance is the distance to the edge's circle less s, along the ray
// from it; across the tread and the sides it is the square tire's.
TEST(TireShape, ARoundedShoulderIsAQuarterCircleOfItsRadius) {
  TireShape<double> t = tire("slick");
  const TireShape<double> square = t;
  t.shoulder = 0.01;
  const double edge_r = t.radius - t.shoulder, edge_z = 0.5 * t.width - t.shoulder, phi = kPi / 4;
  for (double d : {0.02, 0.01, 0.005, 0.0}) {  // outside, on the surface, inside, the circle's centre
    const double y[3] = {edge_r + d * std::cos(phi), 0, edge_z + d * std::sin(phi)};
    double n[3];
    EXPECT_NEAR(t.distance(y, n), d - t.shoulder, 1e-12);
    if (d > 0) {
      EXPECT_NEAR(n[0], std::cos(phi), 1e-12);
      EXPECT_NEAR(n[2], std::sin(phi), 1e-12);
    }
  }
  const double far_corner[3] = {edge_r + 0.02 * std::cos(phi), 0, edge_z + 0.02 * std::sin(phi)};
  double n[3];
  EXPECT_GT(t.distance(far_corner, n), square.distance(far_corner, n) + 0.004);  // the square corner is nearer
  const double below_tread[3] = {0, -(t.radius + 0.003), 0.01}, beside[3] = {0.05, 0.1, 0.5 * t.width + 0.004};
  EXPECT_NEAR(t.distance(below_tread, n), square.distance(below_tread, n), 1e-15);
  EXPECT_NEAR(t.distance(beside, n), square.distance(beside, n), 1e-15);
}

TEST(TireShape, SkippingFarBlocksChangesNothing) {
  expect_skipping_changes_nothing<float>();
  expect_skipping_changes_nothing<double>();
}

// A distance function must be 1-Lipschitz; the unrolled tread's bending allows a little more.
TEST(TireShape, DistanceIsLipschitzWithinOnePercent) {
  std::mt19937 rng(3);
  std::normal_distribution<double> step(0, 0.002);
  for (const char* tread : kTreads) {
    const TireShape<double> t = tire(tread);
    double worst = 0;
    for (const auto& p : samples(11, 20000)) {
      const double q[3] = {p[0] + step(rng), p[1] + step(rng), p[2] + step(rng)};
      double n[3];
      const double gap = std::sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]));
      worst = std::max(worst, std::fabs(t.distance(p.data(), n) - t.distance(q, n)) / gap);
    }
    EXPECT_LT(worst, 1.01) << tread;
  }
}

// Outside, following the normal back by the distance lands on the surface (to 3% of the
// distance): the magnitude is the distance to the nearest surface, not just a bound. Inside, where
// the union's minimum is only a bound, moving out along the normal by |d| never goes deeper by
// more than 5% of |d| (the normal points out of the solid, or along its surface under a block's
// foot), and never farther than 10% of |d| past the surface (the depth is not overestimated).
TEST(TireShape, ProjectionAlongTheNormalLandsOnTheSurface) {
  for (const char* tread : kTreads) {
    const TireShape<double> t = tire(tread);
    int outside = 0, inside = 0;
    for (const auto& p : samples(5, 20000)) {
      double n[3], m[3];
      const double d = t.distance(p.data(), n);
      if (std::fabs(d) > 0.01 || d == 0) continue;
      const double q[3] = {p[0] - d * n[0], p[1] - d * n[1], p[2] - d * n[2]};
      const double dq = t.distance(q, m);
      if (d > 0) {
        ASSERT_LT(std::fabs(dq), 0.03 * d) << tread;
        ++outside;
      } else {
        ASSERT_GT(dq, 1.05 * d) << tread;
        ASSERT_LT(dq, -0.1 * d) << tread;  // moved out by |d|: at most just past the surface
        ++inside;
      }
    }
    EXPECT_GT(outside, 2000) << tread;
    EXPECT_GT(inside, 2000) << tread;
  }
}

// Scan the tread surface at mid depth around one pitch: which fraction of angles has a block.
double contact_fraction(const TireShape<double>& t, double w_from, double w_to) {
  const double r = t.radius - 0.5 * t.tread_depth;
  int hit = 0, total = 0;
  for (int i = 0; i < 400; ++i, ++total) {
    const double a = 2 * kPi / t.pitches * (i + 0.5) / 400;
    for (int k = 0; k <= 40; ++k) {
      const double z = (w_from + (w_to - w_from) * k / 40) * t.width, y[3] = {r * std::cos(a), r * std::sin(a), z}, *p = y;
      double n[3];
      if (t.distance(p, n) <= 0) {
        ++hit;
        break;
      }
    }
  }
  return double(hit) / total;
}

TEST(TreadPatterns, HaveTheThesisProperties) {
  // Angled footstep: a block in contact at every angle (section 4.3.2).
  EXPECT_EQ(contact_fraction(tire("angled_footstep"), -0.5, 0.5), 1.0);
  // Bowtie: contact is not continuous, and its centre is one flat block.
  EXPECT_LT(contact_fraction(tire("bowtie"), -0.5, 0.5), 0.6);
  EXPECT_NEAR(contact_fraction(tire("bowtie"), -0.05, 0.05), 0.5, 0.01);
  // Six rib: the grooves between the ribs are open (exact, whatever the grid).
  const TireShape<double> six = tire("six_rib");
  double n[3];
  const double r = six.radius - 0.5 * six.tread_depth, a = -kPi / 2 + 0.3 * 2 * kPi / 12;
  const double groove[3] = {r * std::cos(a), r * std::sin(a), 0.0};  // the central groove, 7.5 mm wide
  EXPECT_GT(six.distance(groove, n), 0);
  EXPECT_NEAR(six.distance(groove, n), 0.5 * 0.06 * 0.125, 1e-4);
  EXPECT_GT(contact_fraction(six, 0.05, 0.15), 0.6);
  // A slick tire is a cylinder of the full radius.
  const TireShape<double> slick = tire("slick");
  const double below[3] = {0, -0.195, 0};
  EXPECT_NEAR(slick.distance(below, n), -0.005, 1e-12);
}

}  // namespace
}  // namespace firn
