// Tests written once per backend (DESIGN.md section 8, the Kokkos/Cabana way): each backend's
// launches and the whole step through it. Instantiated for serial and OpenMP by
// test_backend_cases.cpp and for CUDA by test_backend_cases_cuda.cu (FIRN_CUDA builds); an instance
// whose backend cannot run here (no CUDA device) skips, saying why.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/aligned_vector.hpp"
#include "engine/backend_kind.hpp"
#include "engine/block_compaction.hpp"
#include "kernels/block_lists.hpp"
#include "kernels/combine.hpp"
#include "kernels/hd.hpp"
#include "tests/two_bodies.hpp"

namespace firn {

// out[i] = i^2.
struct SquareInto {
  long* out;
  FIRN_HD void operator()(std::size_t i) const { out[i] = long(i) * long(i); }
};

// Partial sums of the harmonic series, H_n = ln n + 0.5772...
struct HarmonicTerm {
  FIRN_HD void operator()(std::size_t i, float& acc) const { acc += 1.0f / float(i + 1); }
};

// Each case runs with its backend's memory space as the default, as the commands do.
template <class Backend>
class BackendCases : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string why = backend_unavailable(backend_named(Backend::kName));
    if (!why.empty()) GTEST_SKIP() << Backend::kName << ": " << why;
  }
  const backend::UseMemorySpace memory_{Backend::memory()};
};

TYPED_TEST_SUITE_P(BackendCases);

// Every coordinate of `outcome` within 1e-5 of the OpenMP backend's run of the same case.
inline void expect_openmp_positions(const TwoBodiesOutcome& outcome, Transfer transfer, Shape shape) {
  const TwoBodiesOutcome reference = openmp_two_bodies(transfer, shape);
  ASSERT_EQ(reference.positions.size(), outcome.positions.size());
  for (std::size_t i = 0; i < outcome.positions.size(); ++i)
    ASSERT_NEAR(reference.positions[i], outcome.positions[i], 1e-5f) << "coordinate " << i;
}

TYPED_TEST_P(BackendCases, ParallelForReachesEveryItem) {
  const std::size_t n = 100003;
  AlignedVector<long> out(n, -1);
  TypeParam{}.parallel_for("square", n, SquareInto{out.data()});
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(out[i], long(i) * long(i)) << "item " << i;
}

TYPED_TEST_P(BackendCases, ParallelReduceRepeatsItsBits) {
  const std::size_t n = 100003;  // several chunks and thread blocks, not a multiple of either
  const float first = TypeParam{}.parallel_reduce("sum", n, 0.0f, HarmonicTerm{}, Sum{});
  EXPECT_NEAR(first, 12.09, 0.01);
  EXPECT_EQ(TypeParam{}.parallel_reduce("sum", n, 0.0f, HarmonicTerm{}, Sum{}), first);
  EXPECT_EQ(TypeParam{}.parallel_reduce("empty", 0, 5.0f, HarmonicTerm{}, Sum{}), 5.0f);
}

// The whole step (binning, constitutive update, the P2G scatter, the grid update, the G2P gather):
// the same state on two runs, and the OpenMP backend's to rounding (1e-3 of a cell).
TYPED_TEST_P(BackendCases, StepRepeatsAndAgreesWithOpenMP) {
  for (const Transfer transfer : {Transfer::apic, Transfer::flip})
    for (const Shape shape : {Shape::quadratic, Shape::cubic}) {
      const TwoBodiesOutcome a = run_two_bodies(TypeParam{}, transfer, shape);
      EXPECT_EQ(run_two_bodies(TypeParam{}, transfer, shape).hash, a.hash);
      expect_openmp_positions(a, transfer, shape);
    }
}

// The block lists of a step by compaction on the backend (kernels/block_lists.hpp) against the
// plain host loops: the particle blocks of two materials' buckets in id order and by parity colour,
// then the active blocks (b + {0,1}^3 of every particle block) in slots of increasing id.
TYPED_TEST_P(BackendCases, BlockListsMatchHostLoops) {
  const BlockBox box{{13, 7, 11}};  // 1001 blocks: four compaction chunks, the last one partial
  const std::size_t blocks = 13 * 7 * 11, materials = 2;
  AlignedVector<std::uint32_t> bucket_begin(materials * blocks + 1, 0);
  for (std::size_t q = 0; q < materials * blocks; ++q) {
    int c[3];
    box.coords(q % blocks, c);
    const bool interior = c[0] < 12 && c[1] < 6 && c[2] < 10;
    const std::uint32_t count = interior && (q * 2654435761u) % 7 == 0 ? std::uint32_t(1 + q % 3) : 0;
    bucket_begin[q + 1] = bucket_begin[q] + count;
  }
  std::vector<std::uint32_t> in_order, by_colour[backend::BlockColouring::kColours];
  std::vector<std::uint8_t> occupied_expected(blocks, 0);
  for (std::size_t b = 0; b < blocks; ++b)
    for (std::size_t m = 0; m < materials; ++m)
      if (bucket_begin[m * blocks + b] != bucket_begin[m * blocks + b + 1]) {
        int c[3];
        box.coords(b, c);
        in_order.push_back(std::uint32_t(b));
        by_colour[backend::block_colour(c[0], c[1], c[2])].push_back(std::uint32_t(b));
        occupied_expected[b] = 1;
        break;
      }
  ASSERT_GT(in_order.size(), 20u);

  const ParticleBlockColour colour{bucket_begin.data(), blocks, materials, box};
  BlockCompaction<backend::BlockColouring::kColours> particle{{"count", "prefix", "write"}};
  const auto begins = particle.count(blocks, colour, TypeParam{});
  ASSERT_EQ(begins.back(), in_order.size());
  AlignedVector<std::uint32_t> listed(in_order.size()), coloured(in_order.size());
  AlignedVector<std::uint8_t> occupied(blocks, 7);
  particle.write(ParticleBlockLists{listed.data(), coloured.data(), occupied.data()}, TypeParam{});
  EXPECT_EQ(std::vector<std::uint32_t>(listed.begin(), listed.end()), in_order);
  EXPECT_EQ(std::vector<std::uint8_t>(occupied.begin(), occupied.end()), occupied_expected);
  for (int k = 0; k < backend::BlockColouring::kColours; ++k)
    EXPECT_EQ(std::vector<std::uint32_t>(coloured.begin() + begins[std::size_t(k)], coloured.begin() + begins[std::size_t(k) + 1]),
              by_colour[k])
        << "colour " << k;

  std::vector<std::uint32_t> active;
  for (std::size_t b = 0; b < blocks; ++b) {
    int c[3];
    box.coords(b, c);
    bool touched = false;
    for (int o = 0; o < 8 && !touched; ++o) {
      const int x = c[0] - (o >> 2), y = c[1] - ((o >> 1) & 1), z = c[2] - (o & 1);
      touched = x >= 0 && y >= 0 && z >= 0 && occupied_expected[box.id(x, y, z)];
    }
    if (touched) active.push_back(std::uint32_t(b));
  }
  const ActiveBlock is_active{occupied.data(), box};
  BlockCompaction<1> activation{{"count", "prefix", "write"}};
  ASSERT_EQ(activation.count(blocks, is_active, TypeParam{})[1], active.size());
  AlignedVector<std::int32_t> map(blocks, 99);
  AlignedVector<std::uint32_t> slots(active.size());
  AlignedVector<int> coords(3 * active.size());
  activation.write(ActiveBlockSlots{map.data(), slots.data(), coords.data(), box}, TypeParam{});
  EXPECT_EQ(std::vector<std::uint32_t>(slots.begin(), slots.end()), active);
  std::size_t mapped = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    if (map[b] < 0) {
      ASSERT_EQ(map[b], -1) << "block " << b;
      continue;
    }
    ++mapped;
    const std::size_t s = std::size_t(map[b]);
    ASSERT_EQ(slots[s], b);
    int c[3];
    box.coords(b, c);
    EXPECT_EQ(coords[3 * s], c[0]);
    EXPECT_EQ(coords[3 * s + 1], c[1]);
    EXPECT_EQ(coords[3 * s + 2], c[2]);
  }
  EXPECT_EQ(mapped, active.size());
}

REGISTER_TYPED_TEST_SUITE_P(BackendCases, ParallelForReachesEveryItem, ParallelReduceRepeatsItsBits,
                            StepRepeatsAndAgreesWithOpenMP, BlockListsMatchHostLoops);

}  // namespace firn
