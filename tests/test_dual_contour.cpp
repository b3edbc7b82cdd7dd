// Dual contouring (viz/dual_contour.hpp): a sphere's faces point outward and its vertices lie on
// it; a box keeps its corners and edges (where marching tetrahedra cut them); the tread of a tire
// keeps its blocks' shoulders.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/tread_patterns.hpp"
#include "viz/dual_contour.hpp"

namespace firn::viz {
namespace {

Vec3 vertex_at(const TriangleMesh& m, std::size_t v) {
  return {m.vertices[6 * v], m.vertices[6 * v + 1], m.vertices[6 * v + 2]};
}
Vec3 normal_at(const TriangleMesh& m, std::size_t v) {
  return {m.vertices[6 * v + 3], m.vertices[6 * v + 4], m.vertices[6 * v + 5]};
}

TEST(DualContour, SphereIsClosedOutwardAndOnTheSurface) {
  const SignedDistance sphere = [](const Vec3& x, Vec3& n) {
    const double r = length(x);
    n = (1 / r) * x;
    return r - 0.3;
  };
  const TriangleMesh m = dual_contour(sphere, {-0.4, -0.4, -0.4}, {0.4, 0.4, 0.4}, 0.02);
  ASSERT_GT(m.vertex_count(), 0u);
  double area = 0;
  for (std::size_t v = 0; v < m.vertex_count(); v += 3) {
    const Vec3 a = vertex_at(m, v), b = vertex_at(m, v + 1), c = vertex_at(m, v + 2);
    EXPECT_GT(dot(normal_at(m, v), a + b + c), 0) << "triangle " << v / 3 << " faces inward";
    area += 0.5 * length(cross(b - a, c - a));
    EXPECT_NEAR(length(a), 0.3, 2e-3);
  }
  EXPECT_NEAR(area, 4 * 3.141592653589793 * 0.09, 0.01 * 4 * 3.141592653589793 * 0.09);
}

TEST(DualContour, BoxKeepsItsCornersWhereMarchingTetrahedraCutThem) {
  // A box whose corners fall between lattice points (half extents not multiples of h).
  const Vec3 half = {0.113, 0.077, 0.051};
  const SignedDistance box = [half](const Vec3& x, Vec3& n) {
    Vec3 q, out = {0, 0, 0};
    std::size_t m = 0;
    for (std::size_t d = 0; d < 3; ++d) {
      q[d] = std::abs(x[d]) - half[d];
      out[d] = q[d] > 0 ? std::copysign(q[d], x[d]) : 0;
      if (q[d] > q[m]) m = d;
    }
    const double o = length(out);
    if (o > 0) {
      n = (1 / o) * out;
      return o;
    }
    n = {0, 0, 0};
    n[m] = std::copysign(1.0, x[m]);
    return q[m];
  };
  const Vec3 lo = {-0.2, -0.2, -0.2}, hi = {0.2, 0.2, 0.2};
  auto nearest_to_corner = [&](const TriangleMesh& m) {
    double best = 1e9;
    for (std::size_t v = 0; v < m.vertex_count(); ++v) best = std::min(best, length(vertex_at(m, v) - half));
    return best;
  };
  const double h = 0.01;
  const double sharp = nearest_to_corner(dual_contour(box, lo, hi, h));
  const double cut = nearest_to_corner(mesh_signed_distance(box, lo, hi, int(std::lround(0.4 / h))));
  EXPECT_LT(sharp, 0.05 * h);
  EXPECT_GT(cut, 0.3 * h);
}

TEST(DualContour, TireTreadKeepsItsBlocksShoulders) {
  const TireShape<double> tire = make_tire_shape("six_rib", 0.2, 0.125, 0.012, 12);
  const SignedDistance sdf = [&](const Vec3& x, Vec3& n) { return tire.distance(x.data(), n.data()); };
  const double h = 0.002;
  const TriangleMesh m = dual_contour(sdf, {-0.21, -0.21, -0.07}, {0.21, 0.21, 0.07}, h);
  // Every vertex within a small fraction of a cell of the surface (the distance is exact near the
  // tread's outside), so shoulders are not bevelled off. Measured: at most 0.19 h, 99% under 0.01 h.
  double worst = 0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    Vec3 n;
    worst = std::max(worst, std::abs(sdf(vertex_at(m, v), n)));
  }
  EXPECT_LT(worst, 0.3 * h);
}

}  // namespace
}  // namespace firn::viz
