// The cost of a collider at one grid node: the tire's signed distance for each tread pattern
// (the thesis compared run time across patterns, section 4.3.2), against a plain cylinder.
// Points are drawn in the shell within two tread depths of the tire, where nodes pay the full
// evaluation; farther nodes return after the bounding-cylinder test.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "engine/tread_patterns.hpp"
#include "kernels/tire_shape.hpp"

namespace firn {
namespace {

void BM_TireDistance(benchmark::State& state, const std::string& tread) {
  const TireShape<float> t = tire_shape_cast<float>(make_tire_shape(tread, 0.2, 0.125, 0.012, 12));  // engine default precision
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> phi(0, 6.2831853f), r(0.176f, 0.224f), z(-0.0625f, 0.0625f);
  std::vector<float> points;
  for (int i = 0; i < 4096; ++i) {
    const float a = phi(rng), rr = r(rng);
    points.insert(points.end(), {rr * std::cos(a), rr * std::sin(a), z(rng)});
  }
  float sum = 0;
  for (auto _ : state)
    for (std::size_t i = 0; i < points.size(); i += 3) {
      float n[3];
      sum += t.distance(&points[i], n);
    }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations() * std::int64_t(points.size() / 3));
}

BENCHMARK_CAPTURE(BM_TireDistance, slick, std::string("slick"));
BENCHMARK_CAPTURE(BM_TireDistance, angled_footstep, std::string("angled_footstep"));
BENCHMARK_CAPTURE(BM_TireDistance, bowtie, std::string("bowtie"));
BENCHMARK_CAPTURE(BM_TireDistance, six_rib, std::string("six_rib"));

}  // namespace
}  // namespace firn
