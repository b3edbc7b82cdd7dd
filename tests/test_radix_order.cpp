// radix_order (engine/radix_order.hpp) puts indices in the order std::stable_sort gives them: keys
// that differ in either 16-bit digit, ties kept in index order, passes with one digit skipped.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "engine/radix_order.hpp"

namespace firn {
namespace {

std::vector<std::uint32_t> stable_order(const std::vector<std::uint32_t>& keys) {
  std::vector<std::uint32_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&keys](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
  return order;
}

void expect_stable_order(const std::vector<std::uint32_t>& keys) {
  std::vector<std::uint32_t> order;
  RadixBuffers buffers;
  radix_order(keys.data(), keys.size(), order, buffers);
  EXPECT_EQ(order, stable_order(keys));
}

TEST(RadixOrder, FullRangeKeysWithTies) {
  std::mt19937 rng(7);
  std::vector<std::uint32_t> keys(20000);
  for (std::uint32_t& k : keys) k = rng() % 3000 == 0 ? 42u : std::uint32_t(rng());
  expect_stable_order(keys);
}

TEST(RadixOrder, ShuffledParticleIdsWithGaps) {
  // ids as a scene leaves them: unique, shuffled by the spatial sort, with holes where particles left.
  std::vector<std::uint32_t> keys;
  for (std::uint32_t id = 0; id < 200000; ++id)
    if (id % 7 != 3) keys.push_back(id);
  std::shuffle(keys.begin(), keys.end(), std::mt19937(11));
  expect_stable_order(keys);
}

TEST(RadixOrder, OneDigitPassesAreSkippedCorrectly) {
  std::mt19937 rng(3);
  std::vector<std::uint32_t> low_only(5000), high_only(5000), equal(300, 0xabcd1234u);
  for (std::uint32_t& k : low_only) k = 0x00050000u | (rng() & 0xffffu);  // high digit uniform
  for (std::uint32_t& k : high_only) k = (rng() & 0xffff0000u) | 0x77u;   // low digit uniform
  expect_stable_order(low_only);
  expect_stable_order(high_only);
  expect_stable_order(equal);
}

TEST(RadixOrder, EmptyAndReusedBuffers) {
  std::vector<std::uint32_t> order(5, 9u);
  RadixBuffers buffers;
  radix_order(nullptr, 0, order, buffers);
  EXPECT_TRUE(order.empty());
  const std::vector<std::uint32_t> keys = {5, 1, 4, 1, 3};
  radix_order(keys.data(), keys.size(), order, buffers);
  EXPECT_EQ(order, (std::vector<std::uint32_t>{1, 3, 4, 2, 0}));
}

}  // namespace
}  // namespace firn
