// The lane form of the constitutive update (kernels/lanes.hpp, kernels/lane_math.hpp,
// HyperelasticPlastic::project_lanes, SnowCamClay::project_lanes, MooneyRivlin::kirchhoff_lanes,
// NeoHookean::kirchhoff_lanes, ConstitutiveUpdateLanes): the lane functions against the C library, the lane return and stress
// against the scalar ones, and a particle's result independent of its batch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "engine/materials.hpp"
#include "engine/particle_storage.hpp"
#include "kernels/lane_math.hpp"
#include "kernels/step/constitutive_update.hpp"

namespace firn {
namespace {

constexpr int kW = batch_width<float>(kHostVectorBytes);  // the engine's batch

template <class T>
T relative_error(T a, T b) {
  return std::fabs(a - b) / std::fabs(b);
}

// A lane function against the C library's, over [lo, hi] in geometric steps.
template <class T, class LaneFunction, class Reference>
void check_against(LaneFunction lanes, Reference reference, double lo, double hi) {
  constexpr int W = lane_width<T>(kHostVectorBytes);
  T worst = 0;
  for (double x = lo; x < hi; x *= 1.0137) {
    const Lanes<T, W> y = lanes(Lanes<T, W>(T(x)));
    worst = std::max(worst, relative_error(y.v[0], reference(T(x))));
  }
  EXPECT_LT(worst, T(4) * std::numeric_limits<T>::epsilon());
}

template <class T>
void check_roots() {
  constexpr int W = lane_width<T>(kHostVectorBytes);
  using L = Lanes<T, W>;
  check_against<T>([](const L& x) { return inverse_cbrt(x); }, [](T x) { return T(1) / std::cbrt(x); }, 1e-6, 1e6);
  check_against<T>([](const L& x) { return sqrt(x); }, [](T x) { return std::sqrt(x); }, 1e-12, 1e12);
  EXPECT_EQ(sqrt(L(T(0))).v[0], T(0));
}

TEST(LaneMath, RootsFloat) { check_roots<float>(); }
TEST(LaneMath, RootsDouble) { check_roots<double>(); }

template <class T>
void check_pow() {
  constexpr int W = lane_width<T>(kHostVectorBytes);
  T worst = 0;
  for (const T n : {T(0.02), T(0.5), T(2.5), T(-1.3)})
    for (double x = 1e-3; x < 1e3; x *= 1.0213) {
      LaneMask<W> ok = LaneMask<W>::all();
      const Lanes<T, W> p = pow_lanes(Lanes<T, W>(T(x)), n, ok);
      ASSERT_TRUE(ok.m[0]) << x;
      // pow's condition number is |n ln x|: an error of one rounding in ln x is that relative error.
      worst = std::max(worst, relative_error(p.v[0], std::pow(T(x), n)) / T(1 + std::fabs(n * std::log(x))));
    }
  EXPECT_LT(worst, T(4) * std::numeric_limits<T>::epsilon());
  LaneMask<W> ok = LaneMask<W>::all();
  Lanes<T, W> x(T(2));
  x.v[0] = T(0);
  if (W > 1) x.v[1] = T(-1);
  pow_lanes(x, T(2000), ok);  // 2^2000 overflows T
  EXPECT_FALSE(ok.m[0]);
  for (int l = 1; l < W && l < 3; ++l) EXPECT_FALSE(ok.m[l]) << l;
}

TEST(LaneMath, PowerFloat) { check_pow<float>(); }
TEST(LaneMath, PowerDouble) { check_pow<double>(); }

// The hardening law skips pow_lanes where every base is 1 (J2Hardening::evaluate): that is exact
// only if pow_lanes gives 1 there, for every finite exponent, and keeps the lanes.
template <class T>
void check_power_of_one() {
  constexpr int W = lane_width<T>(kHostVectorBytes);
  for (const T n : {T(0.02), T(0.5), T(1), T(2.5), T(-1.3), T(40), T(0), T(-0.0)}) {
    LaneMask<W> ok = LaneMask<W>::all();
    const Lanes<T, W> p = pow_lanes(Lanes<T, W>(T(1)), n, ok);
    for (int l = 0; l < W; ++l) {
      EXPECT_EQ(p.v[l], T(1)) << n;
      EXPECT_TRUE(ok.m[l]) << n;
    }
  }
}

TEST(LaneMath, PowerOfOneIsOneFloat) { check_power_of_one<float>(); }
TEST(LaneMath, PowerOfOneIsOneDouble) { check_power_of_one<double>(); }

// largest() against a loop over the lanes: the maximum in every lane in turn, ties, zeros and
// +inf.
TEST(LaneMath, LargestIsTheMaximum) {
  std::mt19937 random(3);
  std::uniform_real_distribution<float> value(0.0f, 1e9f);
  for (int top = 0; top < kW; ++top) {
    Lanes<float, kW> a;
    for (int l = 0; l < kW; ++l) a.v[l] = value(random);
    a.v[top] = 2e9f;
    EXPECT_EQ(largest(a), 2e9f) << top;
    a.v[(top + kW / 2) % kW] = 2e9f;  // a tie
    EXPECT_EQ(largest(a), 2e9f) << top;
    a.v[top] = std::numeric_limits<float>::infinity();
    EXPECT_EQ(largest(a), std::numeric_limits<float>::infinity()) << top;
    a.v[top] = 0.0f;
    a.v[(top + kW / 2) % kW] = 0.0f;
    EXPECT_EQ(largest(a), *std::max_element(a.v, a.v + kW)) << top;
  }
  EXPECT_EQ(largest(Lanes<float, kW>(0.0f)), 0.0f);
}

// Trial states that yield by far: F = I + noise, scaled to J in [0.5, 1] (as
// bench/bench_return_mapping.cpp). Their returns step beyond the series' radius.
std::vector<Mat3<float>> trial_states(int count, double noise_amplitude = 0.25) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> noise(-noise_amplitude, noise_amplitude), volume(0.5, 1.0);
  std::vector<Mat3<float>> F(count);
  for (auto& f : F) {
    Mat3<double> d = Mat3<double>::identity();
    for (double& x : d.m) x += noise(rng);
    d = std::cbrt(volume(rng) / determinant(d)) * d;
    for (int q = 0; q < 9; ++q) f.m[q] = float(d.m[q]);
  }
  return F;
}

const HyperelasticPlastic<float>& hard_snow() {
  static const MaterialModel<float> any = make_material_model<float>(preset_material_info("thesis_hard_snow"));
  return std::get<HyperelasticPlastic<float>>(any);
}

// A step of snow: a state on the yield surface (a returned trial state) after an increment
// F <- (I + G) F with |G_ij| <= 2e-3, as a step's velocity gradient times dt. Most yield again.
std::vector<Mat3<float>> step_states(int count) {
  std::vector<Mat3<float>> F = trial_states(count);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<float> increment(-2e-3f, 2e-3f);
  for (auto& f : F) {
    PlasticState<float> s{0.01f};
    hard_snow().project(f, s);
    Mat3<float> G = Mat3<float>::identity();
    for (float& x : G.m) x += increment(rng);
    f = G * f;
  }
  return F;
}

// Lane return against the scalar one, for a step's increments (all on the lane path) and for large
// ones (beyond the series' radius, which the lane form hands back to the scalar return).
void check_lane_return(const HyperelasticPlastic<float>& model, const std::vector<Mat3<float>>& trial, bool steps) {
  int handed_back = 0, plastic = 0;
  for (std::size_t first = 0; first < trial.size(); first += kW) {
    Mat3<Lanes<float, kW>> F;
    Lanes<float, kW> alpha(0.01f), work(0.f);
    for (int l = 0; l < kW; ++l)
      for (int q = 0; q < 9; ++q) F.m[q].v[l] = trial[first + l].m[q];
    LaneMask<kW> ok = LaneMask<kW>::all();
    Lanes<float, kW> tau[6];
    const LaneMask<kW> yielded = model.project_lanes(F, alpha, work, ok, tau);
    for (int l = 0; l < kW; ++l) {
      if (!ok.m[l]) {
        ++handed_back;
        continue;
      }
      Mat3<float> f = trial[first + l];
      PlasticState<float> s{0.01f};
      float w = 0;
      const bool scalar_yielded = project_measuring_work(model, f, s, &w);
      ASSERT_EQ(yielded.m[l] != 0, scalar_yielded);
      plastic += scalar_yielded;
      for (int q = 0; q < 9; ++q) EXPECT_NEAR(F.m[q].v[l], f.m[q], 2e-6f) << q;
      EXPECT_NEAR(alpha.v[l], s.alpha, 1e-5f * s.alpha);
      EXPECT_NEAR(work.v[l], w, 1e-4f * std::fabs(w) + 1e-3f);
      Mat3<float> returned;
      for (int q = 0; q < 9; ++q) returned.m[q] = F.m[q].v[l];
      if (scalar_yielded) {  // on the yield surface after the return, up to rounding
        EXPECT_LT(std::fabs(model.yield_function(returned, PlasticState<float>{alpha.v[l]})),
                  1e-5f * model.elastic.G1);  // a strain of 1e-5, some 20 float roundings
      }
      // The stress the lane form gives with the return, against the scalar stress of the scalar
      // return's F.
      const Mat3<float> tau_scalar = model.kirchhoff(f);
      const int kTau[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};  // ParticleView::tau's order
      for (int c = 0; c < 6; ++c)
        EXPECT_NEAR(tau[c].v[l], tau_scalar(kTau[c][0], kTau[c][1]), 2e-6f * model.p_wave_modulus()) << c;
    }
  }
  if (steps) {
    EXPECT_EQ(handed_back, 0);
    EXPECT_GT(plastic, int(trial.size()) / 4);
  } else {
    EXPECT_EQ(handed_back, int(trial.size()));
  }
}

TEST(LaneReturn, StepsMatchTheScalarReturn) { check_lane_return(hard_snow(), step_states(64 * kW), true); }
TEST(LaneReturn, LargeReturnsAreHandedBack) { check_lane_return(hard_snow(), trial_states(64 * kW), false); }

// With G2 != 0 the lane form takes the stress of the returned F from Mooney-Rivlin's lanes rather
// than from the return's deviator (HyperelasticPlastic::lane_stress): the same shear modulus split
// 80 / 20 between G1 and G2.
TEST(LaneReturn, StepsMatchTheScalarReturnWithG2) {
  HyperelasticPlastic<float> model = hard_snow();
  model.elastic.G2 = 0.2f * model.elastic.G1;
  model.elastic.G1 *= 0.8f;
  check_lane_return(model, step_states(64 * kW), true);
}

// Mooney-Rivlin's stress in lanes against the scalar one, without and with the G2 term (each a loop
// of its own), in float and double, for F far from the identity (J in [0.5, 1]).
template <class T>
void check_mooney_rivlin_lanes() {
  constexpr int W = batch_width<T>(kHostVectorBytes);
  const std::vector<Mat3<float>> F = trial_states(8 * W);
  for (const T G2 : {T(0), T(3e5)}) {
    const MooneyRivlin<T> model{T(5e6), T(1e6), G2};
    T worst = 0;
    for (std::size_t first = 0; first < F.size(); first += W) {
      Mat3<Lanes<T, W>> Fl;
      for (int l = 0; l < W; ++l)
        for (int q = 0; q < 9; ++q) Fl.m[q].v[l] = T(F[first + l].m[q]);
      Lanes<T, W> tau[6];
      model.kirchhoff_lanes(Fl, tau);
      for (int l = 0; l < W; ++l) {
        Mat3<T> f;
        for (int q = 0; q < 9; ++q) f.m[q] = T(F[first + l].m[q]);
        const Mat3<T> want = model.kirchhoff(f);
        const int kTau[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
        for (int c = 0; c < 6; ++c)
          worst = std::max(worst, std::fabs(tau[c].v[l] - want(kTau[c][0], kTau[c][1])) / model.p_wave_modulus());
      }
    }
    // Relative to the modulus, a few roundings (measured: 0.33 and 0.62 epsilon without and with G2).
    EXPECT_LT(worst, T(8) * std::numeric_limits<T>::epsilon()) << "G2 " << G2;
  }
}

TEST(LaneStress, MooneyRivlinMatchesTheScalarStressFloat) { check_mooney_rivlin_lanes<float>(); }
TEST(LaneStress, MooneyRivlinMatchesTheScalarStressDouble) { check_mooney_rivlin_lanes<double>(); }

// The constitutive update of particles [begin, n] from the given F and plastic scalar (alpha or
// J_P, as the model uses), batched in lanes or one by one: per particle F, tau and the scalar.
template <class Model>
std::pair<std::vector<float>, ConstitutiveSummary> run_update(const Model& model, const std::vector<Mat3<float>>& F,
                                                              const std::vector<float>& state, bool lanes,
                                                              std::size_t begin) {
  const int n = int(F.size()) - 1;
  constexpr bool kState = Model::kUsesAlpha || Model::kUsesJp;  // an elastic model's: none allocated
  ParticleStorage<float> storage;
  if (kState) storage.enable(Model::kUsesAlpha ? Attribute::alpha : Attribute::Jp);
  storage.resize(n + 1);
  ParticleView<float> pv = storage.view();
  float* scalar = Model::kUsesAlpha ? pv.alpha : pv.Jp;
  for (int p = 0; p <= n; ++p) {
    for (int q = 0; q < 9; ++q) pv.F[q][p] = F[p].m[q];
    if (kState) scalar[p] = state[p];
    pv.vol0[p] = 1e-6f;
  }
  const ConstitutiveUpdate<float, Model> one{pv, model, begin, true};
  const std::size_t count = std::size_t(n + 1) - begin;
  ConstitutiveSummary acc;
  if (lanes) {
    const ConstitutiveUpdateLanes<float, Model, kW> batched{one, count};
    for (std::size_t b = 0; b < batched.batches(count); ++b) batched(b, acc);
  } else {
    for (std::size_t i = 0; i < count; ++i) one(i, acc);
  }
  std::vector<float> out;
  for (int p = int(begin); p <= n; ++p) {
    for (int q = 0; q < 9; ++q) out.push_back(pv.F[q][p]);
    for (int c = 0; c < 6; ++c) out.push_back(pv.tau[c][p]);
    out.push_back(kState ? scalar[p] : 0.0f);
  }
  return std::make_pair(out, acc);
}

// The batched update against the scalar one over particles that are not a whole number of
// batches, and each particle's result independent of the batch it falls in (the range shifted by
// one particle).
TEST(LaneReturn, BatchedUpdateIsTheScalarUpdateAndIndependentOfBatching) {
  const HyperelasticPlastic<float>& model = hard_snow();
  const int n = 5 * kW + 3;
  std::vector<Mat3<float>> trial = step_states(n + 1);
  const std::vector<Mat3<float>> large = trial_states(n + 1);
  for (int p = 0; p <= n; p += 7) trial[p] = large[p];  // some lanes of each batch take the scalar path
  const std::vector<float> alpha(n + 1, 0.02f);
  const auto scalar = run_update(model, trial, alpha, false, 0), batched = run_update(model, trial, alpha, true, 0),
             shifted = run_update(model, trial, alpha, true, 1);
  ASSERT_EQ(scalar.first.size(), batched.first.size());
  // F to 2e-6, tau to the stress of a strain of 2e-6 (some 30 float roundings), alpha to 1e-5.
  const float tau_tolerance = 2e-6f * model.p_wave_modulus();
  for (std::size_t k = 0; k < scalar.first.size(); ++k) {
    const std::size_t field = k % 16;
    const float tolerance = field < 9 ? 2e-6f : field < 15 ? tau_tolerance : 1e-5f * scalar.first[k];
    EXPECT_NEAR(batched.first[k], scalar.first[k], tolerance) << "particle " << k / 16 << " field " << field;
  }
  EXPECT_NEAR(batched.second.plastic_work, scalar.second.plastic_work, 1e-4 * scalar.second.plastic_work);
  EXPECT_GT(scalar.second.plastic_work, 0);
  EXPECT_EQ(batched.second.max_modulus, scalar.second.max_modulus);
  EXPECT_EQ(batched.second.first_bad, kNoParticle);
  for (std::size_t k = 0; k < shifted.first.size(); ++k)  // particle p at index p - 1
    EXPECT_EQ(shifted.first[k], batched.first[k + 16]) << k;
}

// Cam-clay snow's lane form checks yield in lanes and hands every particle that yields to the
// scalar return, so F and J_P come out as the scalar update's (elastic ones untouched; returned ones
// to rounding, as the scalar return is inlined into another function there) and the stress within
// rounding. fresh_snow near its rest state (strains of a few 1e-4, J_P compacted, at rest and
// dilated) mostly stays elastic; every third particle is strained far beyond yield, and J_P = 1.02
// (dilated past the softening strain: no strength) yields under any stress.
TEST(LaneReturn, CamClayBatchedUpdateIsTheScalarUpdate) {
  static const MaterialModel<float> any = make_material_model<float>(preset_material_info("fresh_snow"));
  const SnowCamClay<float>& model = std::get<SnowCamClay<float>>(any);
  const int n = 7 * kW + 5;
  std::vector<Mat3<float>> F(n + 1);
  const std::vector<Mat3<float>> large = trial_states(n + 1);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<float> strain(-3e-4f, 3e-4f);
  std::vector<float> Jp(n + 1);
  const float kJp[4] = {1.0f, 0.8f, 1.004f, 1.02f};
  for (int p = 0; p <= n; ++p) {
    F[p] = Mat3<float>::identity();
    for (float& x : F[p].m) x += strain(rng);
    if (p % 3 == 0) F[p] = large[p];
    Jp[p] = kJp[p % 4];
  }
  const auto scalar = run_update(model, F, Jp, false, 0), batched = run_update(model, F, Jp, true, 0),
             shifted = run_update(model, F, Jp, true, 1);
  ASSERT_EQ(scalar.first.size(), batched.first.size());
  const float tau_tolerance = 2e-6f * model.p_wave_modulus();
  int elastic = 0, yielded = 0;
  for (int p = 0; p <= n; ++p) {
    bool changed = scalar.first[16 * p + 15] != Jp[p];
    for (int q = 0; q < 9; ++q) changed = changed || scalar.first[16 * p + q] != F[p].m[q];
    (changed ? yielded : elastic) += 1;
    for (int k = 16 * p; k < 16 * p + 16; ++k) {
      const int field = k % 16;
      if (field >= 9 && field < 15)
        EXPECT_NEAR(batched.first[k], scalar.first[k], tau_tolerance) << "particle " << p << " field " << field;
      else if (changed)  // the scalar return's, inlined into another function there
        EXPECT_NEAR(batched.first[k], scalar.first[k], 2e-6f) << "particle " << p << " field " << field;
      else  // untouched
        EXPECT_EQ(batched.first[k], scalar.first[k]) << "particle " << p << " field " << field;
    }
  }
  EXPECT_GT(elastic, n / 3);
  EXPECT_GT(yielded, n / 3);
  EXPECT_NEAR(batched.second.plastic_work, scalar.second.plastic_work, 1e-4 * scalar.second.plastic_work);
  EXPECT_GT(scalar.second.plastic_work, 0);
  EXPECT_EQ(batched.second.max_modulus, scalar.second.max_modulus);
  EXPECT_EQ(batched.second.first_bad, kNoParticle);
  for (std::size_t k = 0; k < shifted.first.size(); ++k) EXPECT_EQ(shifted.first[k], batched.first[k + 16]) << k;
}

// Neo-Hookean's batched update (an elastic model: the stress alone, with no plastic column
// allocated) is the scalar update to the bit, as it takes ln J from the same C library function and
// the rest by the same operations, and F is left as it was; one particle short of whole batches,
// and a particle that inverted (J < 0: NaN stress) is named as the first bad one by both.
TEST(LaneStress, NeoHookeanBatchedUpdateIsTheScalarUpdate) {
  const NeoHookean<float> model{4e5f, 6e5f};
  const int n = 5 * kW - 2;
  std::vector<Mat3<float>> F = trial_states(n + 1);
  F[kW + 3] = -1.0f * Mat3<float>::identity();
  const std::vector<float> unused(n + 1, 1.0f);
  const auto scalar = run_update(model, F, unused, false, 0), batched = run_update(model, F, unused, true, 0),
             shifted = run_update(model, F, unused, true, 1);
  ASSERT_EQ(scalar.first.size(), batched.first.size());
  const auto bits = [](float x) {
    std::uint32_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  };
  for (std::size_t k = 0; k < scalar.first.size(); ++k) {
    if (std::isnan(scalar.first[k]))
      EXPECT_TRUE(std::isnan(batched.first[k])) << k;
    else
      EXPECT_EQ(bits(batched.first[k]), bits(scalar.first[k])) << "particle " << k / 16 << " field " << k % 16;
    if (k % 16 < 9) {
      EXPECT_EQ(batched.first[k], F[k / 16].m[k % 16]) << k;
    }
  }
  EXPECT_EQ(batched.second.max_modulus, scalar.second.max_modulus);
  EXPECT_EQ(batched.second.max_modulus, double(model.p_wave_modulus()));
  EXPECT_EQ(scalar.second.first_bad, std::size_t(kW + 3));
  EXPECT_EQ(batched.second.first_bad, std::size_t(kW + 3));
  EXPECT_EQ(shifted.second.first_bad, std::size_t(kW + 3));
  EXPECT_EQ(batched.second.plastic_work, 0.0);
  for (std::size_t k = 0; k < shifted.first.size(); ++k) {
    if (!std::isnan(batched.first[k + 16])) {
      EXPECT_EQ(shifted.first[k], batched.first[k + 16]) << k;
    }
  }
}

}  // namespace
}  // namespace firn
