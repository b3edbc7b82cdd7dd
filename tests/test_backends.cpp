// The OpenMP backend must produce bitwise identical states at 1 and 2 threads (DESIGN.md section 2,
// rule 7), for every transfer scheme and shape function, with two materials and an adaptive time
// step. The serial reference backend runs the same kernels inlined into other loops, where the
// compiler may fuse multiply-adds differently, so it must agree to rounding, not bit for bit. And
// the OpenMP backend's schedules put their launches on every thread where they should.
#include <gtest/gtest.h>

#include <omp.h>

#include <chrono>
#include <cstdint>
#include <tuple>
#include <vector>

#include "engine/simulation.hpp"
#include "kernels/backend/openmp.hpp"
#include "kernels/backend/serial.hpp"
#include "tests/two_bodies.hpp"

namespace firn {

TwoBodiesOutcome openmp_two_bodies(Transfer transfer, Shape shape) {
  const backend::OpenMP two(2);
  return run_two_bodies(two, transfer, shape);
}

namespace {

class BackendsAgree : public ::testing::TestWithParam<std::tuple<Transfer, Shape>> {};

TEST_P(BackendsAgree, BitwiseForAnyThreadCount) {
  const auto [transfer, shape] = GetParam();
  const backend::OpenMP one(1), two(2);
  const TwoBodiesOutcome a = run_two_bodies(one, transfer, shape), b = run_two_bodies(two, transfer, shape);
  EXPECT_EQ(a.hash, b.hash);
  const TwoBodiesOutcome serial = run_two_bodies(backend::Serial{}, transfer, shape);
  ASSERT_EQ(serial.positions.size(), a.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i)
    ASSERT_NEAR(serial.positions[i], a.positions[i], 1e-5f) << "coordinate " << i;  // 1e-3 of a cell
}

INSTANTIATE_TEST_SUITE_P(AllSchemes, BackendsAgree,
                         ::testing::Combine(::testing::Values(Transfer::apic, Transfer::pic, Transfer::flip),
                                            ::testing::Values(Shape::quadratic, Shape::cubic)));

TEST(StateHash, ChangesWithTheState) {
  SimulationConfig c;
  Simulation<float, backend::Serial> sim(c);
  const int m = sim.add_material({"m", "neo_hookean", 1000, ElasticModuli::from_E_nu(1e5, 0.3)});
  sim.add_particles(m, fill_box(c.domain_min, c.dx, 2, {0.4, 0.4, 0.4}, {0.5, 0.5, 0.5}), {0, 0, 0}, 1e-7);
  sim.prepare();
  const std::uint64_t before = sim.state_hash();
  sim.particles().v[1][7] += 1e-3f;
  EXPECT_NE(sim.state_hash(), before);
}

TEST(ParallelReduce, SameResultOnEveryBackend) {
  const std::size_t n = 100003;  // several chunks, not a multiple of the grain
  auto term = [](std::size_t i, float& acc) { acc += 1.0f / float(i + 1); };
  auto sum = [](float& a, float b) { a += b; };
  const float serial = backend::Serial{}.parallel_reduce("sum", n, 0.0f, term, sum);
  const backend::OpenMP two(2);
  EXPECT_EQ(two.parallel_reduce("sum", n, 0.0f, term, sum), serial);
  EXPECT_NEAR(serial, 12.09, 0.01);  // harmonic number H_n = ln n + 0.5772
}

// The OpenMP team's threads that ran a launch of `n` items under `schedule`, as a bit set, each
// item busy for about `work` (so that one thread cannot take every item before the other starts).
unsigned threads_used(backend::Schedule schedule, std::size_t n, std::chrono::microseconds work) {
  const backend::OpenMP two(2);
  std::vector<int> ran(n, -1);
  two.parallel_for(
      "threads", n,
      [&](std::size_t i) {
        ran[i] = omp_get_thread_num();
        const auto until = std::chrono::steady_clock::now() + work;
        while (std::chrono::steady_clock::now() < until) {
        }
      },
      schedule);
  unsigned used = 0;
  for (int t : ran) used |= 1u << t;
  return used;
}

// A job cut into one part per thread runs each part on its own thread, and grid blocks from 64 on
// are shared, where as uniform items under the 4096-item threshold they run on one thread (the
// counting sort's two parts and the grid update did, issue 15).
TEST(ParallelFor, PartsAndBlocksRunOnEveryThread) {
  EXPECT_EQ(threads_used(backend::Schedule::parts, 2, std::chrono::microseconds(0)), 0b11u);
  EXPECT_EQ(threads_used(backend::Schedule::blocks, 64, std::chrono::microseconds(1000)), 0b11u);
  EXPECT_EQ(threads_used(backend::Schedule::uniform, 64, std::chrono::microseconds(0)), 0b01u);
}

}  // namespace
}  // namespace firn
