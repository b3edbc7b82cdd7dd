// Microbenchmark of the whole constitutive update of yielding snow (return mapping, stress, write
// back; kernels/step/constitutive_update.hpp), one particle at a time (ConstitutiveUpdate) against
// batches of lanes (ConstitutiveUpdateLanes, issue 15; `lanes` the engine's batch of two vectors,
// `one_vector` a batch of one), float, one thread, on
// 65,536 particles of thesis_hard_snow in a step's state: a trial state returned to the yield
// surface, then an increment F <- (I + G) F with |G_ij| <= 2e-3 (fixed seed), so that nearly every
// particle yields again, as the snow of the tire scenes does at every step; and the same for
// fresh_snow (Cam-clay) strained within its elastic range, where the lanes hold the yield check
// only (SnowCamClay::project_lanes). Items are particles.
//   build/release/bench/firn_bench_kernels --benchmark_filter=constitutive
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "engine/materials.hpp"
#include "engine/particle_storage.hpp"
#include "kernels/step/constitutive_update.hpp"

namespace firn {
namespace {

constexpr int kParticles = 1 << 16;

struct StepStates {
  HyperelasticPlastic<float> model;
  std::vector<Mat3<float>> F;
};

const StepStates& step_states() {
  static const StepStates states = [] {
    StepStates s{std::get<HyperelasticPlastic<float>>(make_material_model<float>(preset_material_info("thesis_hard_snow"))),
                 {}};
    std::mt19937_64 rng(20261127);
    std::uniform_real_distribution<double> noise(-0.25, 0.25);
    std::uniform_real_distribution<float> increment(-2e-3f, 2e-3f);
    s.F.resize(kParticles);
    for (auto& f : s.F) {
      Mat3<double> d = Mat3<double>::identity();
      for (double& x : d.m) x += noise(rng);
      d = std::cbrt(1.0 / determinant(d)) * d;
      for (int q = 0; q < 9; ++q) f.m[q] = float(d.m[q]);
      PlasticState<float> state{0.01f};
      s.model.project(f, state);
      Mat3<float> G = Mat3<float>::identity();
      for (float& x : G.m) x += increment(rng);
      f = G * f;
    }
    return s;
  }();
  return states;
}

// fresh_snow (Cam-clay) at rest density, strained by |F_ij - I_ij| <= 3e-4 (fixed seed): every
// particle stays elastic, as most of a snow bed does outside a tire's rut.
struct ElasticStates {
  SnowCamClay<float> model;
  std::vector<Mat3<float>> F;
};

const ElasticStates& elastic_states() {
  static const ElasticStates states = [] {
    ElasticStates s{std::get<SnowCamClay<float>>(make_material_model<float>(preset_material_info("fresh_snow"))), {}};
    std::mt19937_64 rng(20261127);
    std::uniform_real_distribution<float> strain(-3e-4f, 3e-4f);
    s.F.assign(kParticles, Mat3<float>::identity());
    for (auto& f : s.F)
      for (float& x : f.m) x += strain(rng);
    return s;
  }();
  return states;
}

// The update of kParticles particles from the states F and the plastic scalar `scalar0` (alpha or
// J_P, as the model uses), one at a time (W = 0) or in batches of W lanes.
template <int W, class Model>
void run_update(benchmark::State& state, const Model& model, const std::vector<Mat3<float>>& F, float scalar0) {
  ParticleStorage<float> storage;
  storage.enable(Model::kUsesAlpha ? Attribute::alpha : Attribute::Jp);
  storage.resize(kParticles);
  const ParticleView<float> pv = storage.view();
  float* scalar = Model::kUsesAlpha ? pv.alpha : pv.Jp;
  const ConstitutiveUpdate<float, Model> one{pv, model, 0, true};
  for (auto _ : state) {
    state.PauseTiming();
    for (int p = 0; p < kParticles; ++p) {
      for (int q = 0; q < 9; ++q) pv.F[q][p] = F[p].m[q];
      scalar[p] = scalar0;
      pv.vol0[p] = 1e-6f;
    }
    state.ResumeTiming();
    ConstitutiveSummary acc;
    if constexpr (W > 0) {
      const ConstitutiveUpdateLanes<float, Model, W> batched{one, kParticles};
      for (std::size_t b = 0; b < batched.batches(kParticles); ++b) batched(b, acc);
    } else {
      for (std::size_t i = 0; i < std::size_t(kParticles); ++i) one(i, acc);
    }
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * kParticles);
  state.counters["lanes"] = W > 0 ? W : 1;
}

// The engine's batch (kernels/lanes.hpp: two vectors), one vector, and one particle at a time.
constexpr int kBatch = batch_width<float>(kHostVectorBytes), kVector = lane_width<float>(kHostVectorBytes);

template <int W>
void BM_HyperelasticPlastic(benchmark::State& state) {
  run_update<W>(state, step_states().model, step_states().F, 0.01f);
}

template <int W>
void BM_CamClayElastic(benchmark::State& state) {
  run_update<W>(state, elastic_states().model, elastic_states().F, 1.0f);
}

const bool registered =
    (benchmark::RegisterBenchmark("constitutive/hyperelastic_plastic/scalar", BM_HyperelasticPlastic<0>),
     benchmark::RegisterBenchmark("constitutive/hyperelastic_plastic/lanes", BM_HyperelasticPlastic<kBatch>),
     benchmark::RegisterBenchmark("constitutive/hyperelastic_plastic/one_vector", BM_HyperelasticPlastic<kVector>),
     benchmark::RegisterBenchmark("constitutive/snow_cam_clay_elastic/scalar", BM_CamClayElastic<0>),
     benchmark::RegisterBenchmark("constitutive/snow_cam_clay_elastic/lanes", BM_CamClayElastic<kBatch>),
     benchmark::RegisterBenchmark("constitutive/snow_cam_clay_elastic/one_vector", BM_CamClayElastic<kVector>), true);

}  // namespace
}  // namespace firn
