// Microbenchmark of the plastic return mappings alone, the part of the constitutive update that a
// yielding particle adds to the elastic one: hyperelastic_plastic (J2, thesis hard snow) and
// snow_cam_clay (fresh_snow), float, on 4096 trial states that all yield (F = I + uniform noise in
// [-0.25, 0.25] per entry, fixed seed, scaled to J in [0.5, 1]; Cam-clay's also compacted below its
// consolidation pressure). Each iteration projects copies of the same trial states, so every
// projection takes the plastic path. Items are particles: items_per_second is returns per second
// on one thread. `return/*/elastic` starts from the same states after one return, on the yield
// surface up to rounding: in float a share of them (plastic_share, about half for the J2 return)
// lands a rounding outside and returns again, by a vanishing amount.
//   build/release/bench/firn_bench_kernels --benchmark_filter=return
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "engine/materials.hpp"

namespace firn {
namespace {

constexpr int kCount = 4096;

std::vector<Mat3<float>> trial_states() {
  std::mt19937_64 rng(20261125);
  std::uniform_real_distribution<double> noise(-0.25, 0.25), volume(0.5, 1.0);
  std::vector<Mat3<float>> F(kCount);
  for (auto& f : F) {
    Mat3<double> d = Mat3<double>::identity();
    for (double& x : d.m) x += noise(rng);
    if (!(determinant(d) > 0.2)) d = Mat3<double>::identity() + 0.1 * d;  // keep it far from inversion
    d = std::cbrt(volume(rng) / determinant(d)) * d;
    for (int q = 0; q < 9; ++q) f.m[q] = float(d.m[q]);
  }
  return F;
}

template <class Model>
void BM_Return(benchmark::State& state, const std::string& preset, bool plastic) {
  const MaterialModel<float> any = make_material_model<float>(preset_material_info(preset));
  const Model& model = std::get<Model>(any);
  const std::vector<Mat3<float>> trial = trial_states();
  std::vector<Mat3<float>> start = trial;
  std::vector<PlasticState<float>> state0(kCount);
  if (!plastic)  // on the yield surface already, up to rounding
    for (int i = 0; i < kCount; ++i) model.project(start[i], state0[i]);
  std::vector<Mat3<float>> F(kCount);
  std::vector<PlasticState<float>> s(kCount);
  long returns = 0;
  for (auto _ : state) {
    state.PauseTiming();
    F = start;
    s = state0;
    state.ResumeTiming();
    for (int i = 0; i < kCount; ++i) returns += model.project(F[i], s[i]);
    benchmark::DoNotOptimize(F.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kCount);
  state.counters["plastic_share"] = double(returns) / double(state.iterations() * kCount);
}

void register_all() {
  for (const bool plastic : {true, false}) {
    const std::string path = plastic ? "/plastic" : "/elastic";
    benchmark::RegisterBenchmark(("return/hyperelastic_plastic" + path).c_str(),
                                 BM_Return<HyperelasticPlastic<float>>, std::string("thesis_hard_snow"), plastic);
    benchmark::RegisterBenchmark(("return/snow_cam_clay" + path).c_str(), BM_Return<SnowCamClay<float>>,
                                 std::string("fresh_snow"), plastic);
  }
}

const bool registered = (register_all(), true);

}  // namespace
}  // namespace firn
