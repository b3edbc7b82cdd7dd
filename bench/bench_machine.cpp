// The machine's two roofline ceilings, measured the way the step would meet them:
//   machine/triad      a[i] = b[i] + s c[i] over three 64 MB float arrays (McCalpin's STREAM
//                      triad), bytes_per_second counts the 12 bytes STREAM counts per element;
//   machine/peak_fma   independent float multiply-adds in registers (2 flops each), as wide as the
//                      compiler vectorises them for this machine (-march=native: AVX-512 or AVX2).
// Argument: OpenMP threads.
//   build/release/bench/firn_bench_kernels --benchmark_filter=machine
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cstddef>
#include <vector>

namespace firn {
namespace {

void BM_Triad(benchmark::State& state) {
  const int threads = int(state.range(0));
  constexpr std::size_t kN = std::size_t(1) << 24;
  std::vector<float> a(kN), b(kN, 1.0f), c(kN, 2.0f);
  const float s = 3.0f;
  for (auto _ : state) {
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t i = 0; i < kN; ++i) a[i] = b[i] + s * c[i];
    benchmark::DoNotOptimize(a.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(3 * sizeof(float) * kN));
}

void BM_PeakFma(benchmark::State& state) {
  const int threads = int(state.range(0));
  constexpr int kChains = 12, kLanes = 16, kRounds = 1 << 16;  // enough chains to cover FMA latency
  for (auto _ : state) {
    float total = 0;
#pragma omp parallel num_threads(threads) reduction(+ : total)
    {
      float acc[kChains][kLanes];
      for (int j = 0; j < kChains; ++j)
        for (int l = 0; l < kLanes; ++l) acc[j][l] = float(l + j);
      const float m = 0.999999f, k = 1e-7f;
      for (int r = 0; r < kRounds; ++r)  // float rounding keeps the compiler from folding rounds
        for (int j = 0; j < kChains; ++j)
          for (int l = 0; l < kLanes; ++l) acc[j][l] = acc[j][l] * m + k;
      for (int j = 0; j < kChains; ++j)
        for (int l = 0; l < kLanes; ++l) total += acc[j][l];
    }
    benchmark::DoNotOptimize(total);
  }
  const double flops = 2.0 * kChains * kLanes * double(kRounds) * threads;
  state.counters["flops"] = benchmark::Counter(flops * double(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_Triad)->Name("machine/triad")->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PeakFma)->Name("machine/peak_fma")->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace firn
