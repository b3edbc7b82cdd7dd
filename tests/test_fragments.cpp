// Fragment counting (engine/fragments.hpp): connected clusters of particles under a link length.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "engine/fragments.hpp"

namespace firn {
namespace {

// An n x n x n lattice of spacing h from `origin`.
void add_block(std::vector<std::array<double, 3>>& x, std::array<double, 3> origin, int n, double h) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) x.push_back({origin[0] + i * h, origin[1] + j * h, origin[2] + k * h});
}

TEST(Fragments, OneLatticeIsOneFragment) {
  std::vector<std::array<double, 3>> x;
  add_block(x, {-0.01, -0.01, -0.01}, 6, 0.002);  // straddles the hash grid's origin
  const FragmentCount f = count_fragments(x, 0.0025, 10);
  EXPECT_EQ(f.fragments, 1u);
  EXPECT_EQ(f.largest, 216u);
}

TEST(Fragments, BlocksFartherApartThanTheLinkAreSeparate) {
  std::vector<std::array<double, 3>> x;
  add_block(x, {0, 0, 0}, 4, 0.002);
  add_block(x, {0.006 + 0.003, 0, 0}, 4, 0.002);  // a 3 mm gap between the blocks' faces
  add_block(x, {0, 0.02, 0}, 3, 0.002);
  EXPECT_EQ(count_fragments(x, 0.0025, 10).fragments, 3u);
  // A link longer than the gap joins the first two.
  EXPECT_EQ(count_fragments(x, 0.0035, 10).fragments, 2u);
}

TEST(Fragments, SprayBelowTheMinimumIsNotAFragment) {
  std::vector<std::array<double, 3>> x;
  add_block(x, {0, 0, 0}, 4, 0.002);
  for (int i = 0; i < 5; ++i) x.push_back({0.1 + 0.05 * i, 0, 0});  // five lone particles
  const FragmentCount f = count_fragments(x, 0.0025, 10);
  EXPECT_EQ(f.fragments, 1u);
  EXPECT_EQ(f.largest, 64u);
  EXPECT_EQ(count_fragments(x, 0.0025, 1).fragments, 6u);
}

}  // namespace
}  // namespace firn
