// Microbenchmark of firn::svd3 (float, double) against Eigen::JacobiSVD on the same 4096 random
// 3x3 matrices (entries uniform in [-1, 1], fixed seed), computing U, sigma and V in every case.
// Items are matrices: items_per_second is decompositions per second on one thread.
#include <benchmark/benchmark.h>

// GCC 12 flags JacobiSVD's singular values as maybe uninitialised once inlined at -O3 (a false
// positive in Eigen 3.4's code, not in this file's).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <Eigen/Dense>
#include <random>
#include <vector>

#include "kernels/svd3.hpp"

namespace {

constexpr int kCount = 4096;  // 4096 * (9 + 9 + 9 + 3) doubles = 0.9 MiB: fits in L2

template <class T>
std::vector<firn::Mat3<T>> random_matrices() {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  std::vector<firn::Mat3<T>> A(kCount);
  for (auto& a : A)
    for (T& x : a.m) x = T(entry(rng));
  return A;
}

template <class T>
void BM_svd3(benchmark::State& state) {
  const std::vector<firn::Mat3<T>> A = random_matrices<T>();
  std::vector<firn::Mat3<T>> U(kCount), V(kCount);
  std::vector<firn::Vec3<T>> sigma(kCount);
  for (auto _ : state) {
    for (int i = 0; i < kCount; ++i) firn::svd3(A[i], U[i], sigma[i], V[i]);
    benchmark::DoNotOptimize(U.data());
    benchmark::DoNotOptimize(V.data());
    benchmark::DoNotOptimize(sigma.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kCount);
}

template <class T>
void BM_eigen_jacobi_svd(benchmark::State& state) {
  using M = Eigen::Matrix<T, 3, 3>;
  const std::vector<firn::Mat3<T>> A = random_matrices<T>();
  std::vector<M> Ae(kCount), U(kCount), V(kCount);
  std::vector<Eigen::Matrix<T, 3, 1>> sigma(kCount);
  for (int i = 0; i < kCount; ++i) Ae[i] = Eigen::Map<const Eigen::Matrix<T, 3, 3, Eigen::RowMajor>>(A[i].m);
  for (auto _ : state) {
    for (int i = 0; i < kCount; ++i) {
      const Eigen::JacobiSVD<M> svd(Ae[i], Eigen::ComputeFullU | Eigen::ComputeFullV);
      U[i] = svd.matrixU();
      V[i] = svd.matrixV();
      sigma[i] = svd.singularValues();
    }
    benchmark::DoNotOptimize(U.data());
    benchmark::DoNotOptimize(V.data());
    benchmark::DoNotOptimize(sigma.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kCount);
}

}  // namespace

BENCHMARK_TEMPLATE(BM_svd3, float);
BENCHMARK_TEMPLATE(BM_svd3, double);
BENCHMARK_TEMPLATE(BM_eigen_jacobi_svd, float);
BENCHMARK_TEMPLATE(BM_eigen_jacobi_svd, double);
