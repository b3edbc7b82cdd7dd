// P2G and G2P kernels on single particles: P2G conserves mass and momentum exactly (the stress
// and affine terms sum to zero over the stencil), and G2P reproduces an affine grid velocity
// field exactly (APIC/MLS), for both shape functions.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/particle_storage.hpp"
#include "kernels/g2p.hpp"
#include "kernels/p2g.hpp"
#include "kernels/shape_functions.hpp"

namespace firn {
namespace {

GridGeometry<double> unit_grid() {
  GridGeometry<double> g{};
  g.dx = 0.1;
  g.inv_dx = 10;
  for (int d = 0; d < 3; ++d) g.nodes[d] = 32;
  return g;
}

void one_particle(ParticleStorage<double>& s) {
  s.enable(Attribute::C);
  s.resize(1);
  ParticleView<double> pv = s.view();
  const double x[3] = {1.234, 1.617, 0.981}, v[3] = {0.3, -1.2, 0.7};
  for (int d = 0; d < 3; ++d) {
    pv.x[d][0] = x[d];
    pv.v[d][0] = v[d];
  }
  for (int q = 0; q < 9; ++q) {
    pv.F[q][0] = (q % 4 == 0) + 0.01 * q;
    pv.C[q][0] = 0.1 * (q - 4);
  }
  for (int c = 0; c < 6; ++c) pv.tau[c][0] = 1e3 * (c + 1);
  pv.mass[0] = 2.5;
  pv.vol0[0] = 1e-3;
}

struct Totals {  // a scatter target that sums everything it receives
  double sums[7] = {0, 0, 0, 0, 0, 0, 0};
  template <int kRow>
  void add_row(int, int, int, const double* v) {
    for (int n = 0; n < kRow; ++n)
      for (int c = 0; c < 4; ++c) sums[c] += v[4 * n + c];
  }
};

template <class ShapeT>
void check_p2g_conserves() {
  ParticleStorage<double> s;
  one_particle(s);
  const ParticleView<double> pv = s.view();
  Totals t;
  p2g_particle<double, ShapeT, Transfer::apic>(pv, 0, unit_grid(), 1e-3, t);
  EXPECT_NEAR(t.sums[0], pv.mass[0], 1e-14);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(t.sums[1 + d], pv.mass[0] * pv.v[d][0], 1e-12);
}

TEST(P2G, ConservesMassAndMomentumQuadratic) { check_p2g_conserves<QuadraticBSpline<double>>(); }
TEST(P2G, ConservesMassAndMomentumCubic) { check_p2g_conserves<CubicBSpline<double>>(); }

struct AffineField {  // v(x) = a + B x at every node (and old velocity = 0)
  GridGeometry<double> g;
  double a[3] = {0.5, -0.25, 1.0};
  double B[9] = {0.1, -0.2, 0.3, 0.05, 0.4, -0.1, -0.3, 0.2, 0.15};
  mutable double row_values[4 * 4] = {};  // up to 4 nodes (cubic) of velocity and a pad (APIC)
  const double* row(int i, int j, int k) const {
    for (int n = 0; n < 4; ++n) {
      const double x[3] = {i * g.dx, j * g.dx, (k + n) * g.dx};
      for (int r = 0; r < 3; ++r)
        row_values[4 * n + r] = a[r] + B[3 * r] * x[0] + B[3 * r + 1] * x[1] + B[3 * r + 2] * x[2];
    }
    return row_values;
  }
};

template <class ShapeT>
void check_g2p_affine() {
  ParticleStorage<double> s;
  one_particle(s);
  ParticleView<double> pv = s.view();
  const double x[3] = {pv.x[0][0], pv.x[1][0], pv.x[2][0]};
  AffineField field{unit_grid()};
  const double dt = 1e-3;
  g2p_particle<double, ShapeT, Transfer::apic>(pv, 0, field.g, dt, 0.0, field);
  for (int r = 0; r < 3; ++r) {
    const double expected = field.a[r] + field.B[3 * r] * x[0] + field.B[3 * r + 1] * x[1] + field.B[3 * r + 2] * x[2];
    EXPECT_NEAR(pv.v[r][0], expected, 1e-12);
    EXPECT_NEAR(pv.x[r][0], x[r] + dt * expected, 1e-12);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(pv.C[3 * r + k][0], field.B[3 * r + k], 1e-11);
  }
}

TEST(G2P, ReproducesAffineFieldQuadratic) { check_g2p_affine<QuadraticBSpline<double>>(); }
TEST(G2P, ReproducesAffineFieldCubic) { check_g2p_affine<CubicBSpline<double>>(); }

TEST(G2P, FlipBlend) {
  // Grid velocity uniform u, old grid velocity 0: FLIP gives alpha (v_p + u) + (1 - alpha) u.
  struct Uniform {
    double value[3 * 8] = {1, 2, 3, 0, 0, 0, 0, 0, 1, 2, 3, 0, 0, 0, 0, 0, 1, 2, 3, 0, 0, 0, 0, 0};
    const double* row(int, int, int) const { return value; }
  } grid;
  ParticleStorage<double> s;
  one_particle(s);
  ParticleView<double> pv = s.view();
  const double v0[3] = {pv.v[0][0], pv.v[1][0], pv.v[2][0]}, alpha = 0.9;
  g2p_particle<double, QuadraticBSpline<double>, Transfer::flip>(pv, 0, unit_grid(), 1e-3, alpha, grid);
  for (int r = 0; r < 3; ++r) EXPECT_NEAR(pv.v[r][0], alpha * (v0[r] + grid.value[r]) + (1 - alpha) * grid.value[r], 1e-12);
}

TEST(G2P, DeformationGradientUpdate) {
  // F <- (I + dt C) F with C the (here uniform) velocity gradient B.
  ParticleStorage<double> s;
  one_particle(s);
  ParticleView<double> pv = s.view();
  Mat3<double> F;
  for (int q = 0; q < 9; ++q) F.m[q] = pv.F[q][0];
  AffineField field{unit_grid()};
  const double dt = 1e-2;
  g2p_particle<double, QuadraticBSpline<double>, Transfer::apic>(pv, 0, field.g, dt, 0.0, field);
  Mat3<double> G;
  for (int q = 0; q < 9; ++q) G.m[q] = (q % 4 == 0) + dt * field.B[q];
  const Mat3<double> expected = G * F;
  for (int q = 0; q < 9; ++q) EXPECT_NEAR(pv.F[q][0], expected.m[q], 1e-12);
}

}  // namespace
}  // namespace firn
