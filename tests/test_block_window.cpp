// The block windows of kernels/block_window.hpp: the single-thread loops (`load`, `flush`, which
// visit the window block by block) give the same values as the node-by-node forms that a GPU
// thread block shares (`load_node`, `flush_node`), for the quadratic and cubic windows, reading
// past the grid's last channel as zero.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "kernels/block_window.hpp"

namespace firn {
namespace {

// A 3 x 3 x 3 box of blocks, all active, slots in reverse order of block id, every value distinct.
struct TestGrid {
  static constexpr int kChannels = 5;
  BlockBox box{{3, 3, 3}};
  std::vector<std::int32_t> map;
  std::vector<float> data;

  TestGrid() {
    const int blocks = box.count[0] * box.count[1] * box.count[2];
    for (int b = 0; b < blocks; ++b) map.push_back(blocks - 1 - b);
    for (int i = 0; i < blocks * kChannels * kBlockNodes; ++i) data.push_back(float(i) * 0.5f + 1.0f);
  }
  SparseGridView<float> view() { return SparseGridView<float>{data.data(), kChannels, map.data(), box}; }
};

template <int kSpan>
void expect_load_matches_nodes(int first) {
  constexpr int kCh = 4;  // first + kCh may pass the grid's 5 channels
  TestGrid grid;
  const int block[3] = {1, 0, 1};
  BlockGather<float, kSpan, kCh> whole, by_node;
  whole.load(grid.view(), first, block);
  by_node.set_origin(block);
  for (int n = 0; n < by_node.kNodes; ++n) by_node.load_node(grid.view(), first, n);
  for (int i = 0; i < by_node.kNodes * kCh; ++i) ASSERT_EQ(whole.values[i], by_node.values[i]) << "value " << i;
  const bool past_last = first + kCh - 1 >= TestGrid::kChannels;  // every grid value is at least 1
  EXPECT_EQ(whole.values[kCh - 1] == 0.0f, past_last);
}

template <int kSpan>
void expect_flush_matches_nodes() {
  constexpr int kCh = TestGrid::kChannels;
  TestGrid whole, by_node;
  const int block[3] = {0, 1, 1};
  BlockScratch<float, kSpan, kCh> scratch;
  scratch.reset(block);
  for (int i = 0; i < scratch.kNodes * kCh; ++i) scratch.values[i] = float(i % 97) * 0.25f - 7.0f;
  scratch.flush(whole.view());
  for (int n = 0; n < scratch.kNodes; ++n) scratch.flush_node(by_node.view(), n);
  EXPECT_EQ(whole.data, by_node.data);
  EXPECT_NE(whole.data, TestGrid().data);  // the flush added something
}

TEST(BlockWindow, QuadraticLoadMatchesNodeByNode) {
  expect_load_matches_nodes<kBlockSize + 2>(0);
  expect_load_matches_nodes<kBlockSize + 2>(3);  // channels 3 .. 6 of 5: the last two read zero
}

TEST(BlockWindow, CubicLoadMatchesNodeByNode) { expect_load_matches_nodes<kBlockSize + 3>(1); }

TEST(BlockWindow, QuadraticFlushMatchesNodeByNode) { expect_flush_matches_nodes<kBlockSize + 2>(); }

TEST(BlockWindow, CubicFlushMatchesNodeByNode) { expect_flush_matches_nodes<kBlockSize + 3>(); }

}  // namespace
}  // namespace firn
