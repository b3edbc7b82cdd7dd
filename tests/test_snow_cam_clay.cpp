// Cam-clay snow (kernels/constitutive/snow_cam_clay.hpp; Gaume et al. 2018, Wolper et al. 2019):
// the hardening law's branches, the elastic path, the return on the wet and dry sides and past both
// tips (the material driver's closed forms are in firn verify, material_driver_snow_cam_clay),
// float precision.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/materials.hpp"
#include "kernels/constitutive/snow_cam_clay.hpp"

namespace firn {
namespace {

// fresh_snow's parameters (engine/material_catalog.cpp) written out, so a change there shows here.
template <class T>
SnowCamClay<T> fresh_snow() {
  const double E = 4.968e6, nu = 0.2, K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  return SnowCamClay<T>{MooneyRivlin<T>{T(K), T(G), T(0)}, T(1.722), T(2.175),
                        CamClayHardening<T>{T(6283), T(220), T(83.06), T(0.01)}};
}

double pressure(const Mat3<double>& tau) { return -trace(tau) / 3; }

TEST(CamClayHardening, BranchesMeet) {
  const CamClayHardening<double> h{5179, 220, 83.06, 0.01};
  EXPECT_DOUBLE_EQ(h.pressure(0), 5179);
  EXPECT_NEAR(h.pressure(-1e-12), 5179, 1e-5);
  EXPECT_DOUBLE_EQ(h.pressure(-0.01), 0);
  EXPECT_DOUBLE_EQ(h.pressure(-0.5), 0);
  // Compaction to 550 kg/m^3: p0 = p0(rest) exp((550 - 220) / 83.06).
  EXPECT_NEAR(h.pressure(std::log(550.0 / 220)), 5179 * std::exp(330 / 83.06), 1e-6);
}

TEST(SnowCamClay, SmallStrainIsElasticAndLeavesEverythingAlone) {
  const SnowCamClay<double> m = fresh_snow<double>();
  Mat3<double> F = {{1.0002, 0.0001, 0, 0, 0.9999, 0, 0, 0, 1}};
  const Mat3<double> before = F;
  PlasticState<double> s;
  EXPECT_LT(m.yield_function(F, s), 0);
  EXPECT_FALSE(m.project(F, s));
  for (int q = 0; q < 9; ++q) EXPECT_EQ(F.m[q], before.m[q]);
  EXPECT_EQ(s.Jp, 1);
}

// Shear under a little pressure: the wet side of the ellipse (p > p_c = (1 - beta) p0 / 2 < 0 for
// fresh snow), where the return toward the centre lowers p: the snow compacts and hardens.
TEST(SnowCamClay, ShearOnTheWetSideCompactsAndHardens) {
  const SnowCamClay<double> m = fresh_snow<double>();
  const double J = 0.9995;
  Mat3<double> F = std::cbrt(J) * Mat3<double>{{1, 0.05, 0, 0, 1, 0, 0, 0, 1}};
  PlasticState<double> s;
  ASSERT_GT(m.yield_function(F, s), 0);
  EXPECT_TRUE(m.project(F, s));
  EXPECT_LT(s.Jp, 1);
  EXPECT_GT(m.consolidation_pressure(s), m.hardening.p_c0);
  EXPECT_NEAR(determinant(F) * s.Jp, J, 1e-14);
  const double p0 = m.consolidation_pressure(s);
  EXPECT_NEAR(m.yield_function(F, s), 0, 1e-9 * p0 * p0);
}

// Shear under tension, the dry side: the return raises p, the snow dilates and softens.
TEST(SnowCamClay, ShearOnTheDrySideDilatesAndSoftens) {
  const SnowCamClay<double> m = fresh_snow<double>();
  Mat3<double> F = Mat3<double>{{1.0012, 0.05, 0, 0, 1.0012, 0, 0, 0, 1.0012}};
  PlasticState<double> s;
  ASSERT_GT(m.yield_function(F, s), 0);
  ASSERT_LT(pressure(m.kirchhoff(F)), (1 - m.beta) / 2 * m.hardening.p_c0);
  EXPECT_TRUE(m.project(F, s));
  EXPECT_GT(s.Jp, 1);
  EXPECT_LT(m.consolidation_pressure(s), m.hardening.p_c0);
  const double p0 = m.hardening.p_c0;
  EXPECT_NEAR(m.yield_function(F, s), 0, 1e-9 * p0 * p0);
}

// Pulled along x with the lateral contraction of uniaxial stress (nu = 0.2): fresh snow's centre lies
// in tension (beta 2.175 > 1) and the trial between it and p = 0, where a return toward the centre
// would compact the snow. From the origin it dilates, and further pulling takes all its strength
// (softening_strain 1%): the stress falls to zero, the bar has broken.
TEST(SnowCamClay, UniaxialTensionDilatesAndBreaksWhereTheCentreIsInTension) {
  const SnowCamClay<double> m = fresh_snow<double>();
  const auto pulled = [](double e) { return Mat3<double>{{1 + e, 0, 0, 0, 1 - 0.2 * e, 0, 0, 0, 1 - 0.2 * e}}; };
  Mat3<double> F = pulled(0.0016);  // 9% past the strain at Sigrist's tensile strength, 0.147%
  PlasticState<double> s;
  ASSERT_GT(m.yield_function(F, s), 0);
  const double p_trial = pressure(m.kirchhoff(F)) / determinant(F);
  ASSERT_GT(p_trial, (1 - m.beta) / 2 * m.hardening.p_c0);  // the wet side of the centre
  ASSERT_LT(p_trial, 0);
  EXPECT_TRUE(m.project(F, s));
  EXPECT_GT(s.Jp, 1);
  EXPECT_LT(m.consolidation_pressure(s), m.hardening.p_c0);
  const double p0 = m.consolidation_pressure(s);
  EXPECT_NEAR(m.yield_function(F, s), 0, 1e-9 * m.hardening.p_c0 * m.hardening.p_c0);
  EXPECT_GT(p0, 0);
  // 2% more, in steps of 0.05%: the strength falls at every step until none is left (a return
  // toward the centre hardens the snow on the first steps of this path).
  double previous = p0;
  for (int step = 0; step < 40; ++step) {
    F = pulled(0.0005) * F;
    m.project(F, s);
    const double now = m.consolidation_pressure(s);
    if (previous > 0)
      EXPECT_LT(now, previous) << step;
    else
      EXPECT_EQ(now, 0) << step;
    previous = now;
  }
  EXPECT_EQ(m.consolidation_pressure(s), 0);
  const Mat3<double> tau = m.kirchhoff(F);
  for (int q = 0; q < 9; ++q) EXPECT_NEAR(tau.m[q], 0, 1e-9 * m.hardening.p_c0) << q;
}

TEST(SnowCamClay, CompressionPastTheTipCompactsAndHardens) {
  const SnowCamClay<double> m = fresh_snow<double>();
  Mat3<double> F = std::cbrt(0.8) * Mat3<double>::identity();  // 220 -> 275 kg/m^3 in one step
  PlasticState<double> s;
  EXPECT_TRUE(m.project(F, s));
  EXPECT_LT(s.Jp, 1);
  // The Cauchy pressure tau / J at the tip, J = 0.8 the total volume ratio.
  const double p = pressure(m.kirchhoff(F)) / 0.8, p0 = m.consolidation_pressure(s);
  EXPECT_GT(p0, m.hardening.p_c0);
  EXPECT_NEAR(p, p0, 1e-9 * p0);
  EXPECT_NEAR(determinant(F) * s.Jp, 0.8, 1e-14);
}

// Hydrostatic tension past the tensile tip: the return ends at the tip of the softened ellipse,
// p = -beta p0(J_P,new) in Cauchy stress.
TEST(SnowCamClay, StretchPastTheTensileTipSoftens) {
  const SnowCamClay<double> m = fresh_snow<double>();
  const double J = 1 + 1.5 * m.beta * m.hardening.p_c0 / m.elastic.K;  // half as far again as the tip
  Mat3<double> F = std::cbrt(J) * Mat3<double>::identity();
  PlasticState<double> s;
  EXPECT_TRUE(m.project(F, s));
  EXPECT_GT(s.Jp, 1);
  const double p0 = m.consolidation_pressure(s);
  EXPECT_LT(p0, m.hardening.p_c0);
  EXPECT_NEAR(pressure(m.kirchhoff(F)) / J, -m.beta * p0, 1e-9 * m.hardening.p_c0);
}

TEST(SnowCamClay, FloatReturnMatchesDouble) {
  const SnowCamClay<double> md = fresh_snow<double>();
  const SnowCamClay<float> mf = fresh_snow<float>();
  const Mat3<double> start = std::cbrt(0.7) * Mat3<double>{{1, 0.2, 0, 0.01, 1, 0, 0, 0, 1.02}};
  Mat3<double> Fd = start;
  Mat3<float> Ff;
  for (int q = 0; q < 9; ++q) Ff.m[q] = float(start.m[q]);
  PlasticState<double> sd;
  PlasticState<float> sf;
  EXPECT_TRUE(md.project(Fd, sd));
  EXPECT_TRUE(mf.project(Ff, sf));
  EXPECT_NEAR(sf.Jp, sd.Jp, 1e-5);
  const Mat3<double> tau_d = md.kirchhoff(Fd);
  const Mat3<float> tau_f = mf.kirchhoff(Ff);
  for (int q = 0; q < 9; ++q) EXPECT_NEAR(tau_f.m[q], tau_d.m[q], 2e-3 * md.consolidation_pressure(sd)) << q;
}

TEST(SnowCamClay, CatalogPresetBuildsThisModel) {
  const MaterialPreset* preset = find_material_preset("fresh_snow");
  ASSERT_NE(preset, nullptr);
  EXPECT_EQ(preset->model, "snow_cam_clay");
}

}  // namespace
}  // namespace firn
