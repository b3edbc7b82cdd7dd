// ParticleStorage (engine/particle_storage.hpp): a reorder moves every enabled column, real and
// index alike, by the same order (new[i] = old[order[i]]), drops what the order leaves out, and
// leaves the stress columns alone when asked to; the columns are gathered a group at a time, so
// the test enables a column count that is not a multiple of the group.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/particle_storage.hpp"
#include "kernels/backend/serial.hpp"

namespace firn {
namespace {

// A value that names its column and particle: 1000 column + particle.
float tag(int column, std::size_t particle) { return float(1000 * column) + float(particle); }

// Fills every enabled real column with tag(column, particle) in view order and the ids with
// 7 + particle; returns the number of real columns filled.
int fill(ParticleStorage<float>& storage) {
  ParticleView<float> v = storage.view();
  int column = 0;
  auto fill_column = [&](float* c) {
    if (c == nullptr) return;
    for (std::size_t p = 0; p < v.n; ++p) c[p] = tag(column, p);
    ++column;
  };
  for (int d = 0; d < 3; ++d) fill_column(v.x[d]);
  for (int d = 0; d < 3; ++d) fill_column(v.v[d]);
  for (int q = 0; q < 9; ++q) fill_column(v.C[q]);
  for (int q = 0; q < 9; ++q) fill_column(v.F[q]);
  for (int q = 0; q < 6; ++q) fill_column(v.tau[q]);
  fill_column(v.mass);
  fill_column(v.vol0);
  fill_column(v.alpha);
  for (std::size_t p = 0; p < v.n; ++p) v.id[p] = std::uint32_t(7 + p);
  return column;
}

TEST(ParticleStorage, GatherMovesEveryColumnByTheOrderAndDropsTheRest) {
  for (const bool stress : {true, false}) {
    ParticleStorage<float> storage;
    storage.resize(10);
    storage.enable(Attribute::C);
    storage.enable(Attribute::alpha);  // 3 + 3 + 9 + 9 + 6 + 3 = 33 real columns
    ASSERT_EQ(fill(storage), 33);
    const std::vector<std::uint32_t> order = {9, 0, 4, 4, 2, 7};  // a repeat, and 1, 3, 5, 6, 8 dropped
    storage.gather(order.data(), order.size(), backend::Serial{}, stress);
    ASSERT_EQ(storage.size(), order.size());

    const ParticleView<float> v = storage.view();
    int column = 0;
    auto check_column = [&](const float* c, bool moved) {
      for (std::size_t i = 0; i < order.size(); ++i)
        EXPECT_EQ(c[i], tag(column, moved ? order[i] : i)) << "column " << column << ", particle " << i;
      ++column;
    };
    for (int d = 0; d < 3; ++d) check_column(v.x[d], true);
    for (int d = 0; d < 3; ++d) check_column(v.v[d], true);
    for (int q = 0; q < 9; ++q) check_column(v.C[q], true);
    for (int q = 0; q < 9; ++q) check_column(v.F[q], true);
    for (int q = 0; q < 6; ++q) check_column(v.tau[q], stress);  // left in place: the first six
    check_column(v.mass, true);
    check_column(v.vol0, true);
    check_column(v.alpha, true);
    for (std::size_t i = 0; i < order.size(); ++i) EXPECT_EQ(v.id[i], 7 + order[i]);
  }
}

// The spares a gather leaves behind are reused by the next one, grown where the store has grown,
// and the index columns (the ids and the loads) are gathered as a group of their own.
TEST(ParticleStorage, RepeatedGathersOfAGrownStoreMoveEveryColumn) {
  ParticleStorage<float> storage;
  storage.resize(4);
  storage.enable(Attribute::load);
  storage.gather(std::vector<std::uint32_t>{3, 2, 1, 0}.data(), 4, backend::Serial{});
  storage.resize(12);  // more particles than the spares hold
  const int reals = fill(storage);
  ASSERT_EQ(reals, 23);  // x, v, F, tau, mass, vol0: six groups of four, the last of three
  const ParticleView<float> before = storage.view();
  for (std::size_t p = 0; p < before.n; ++p) before.load[p] = std::uint32_t(100 + p);
  const std::vector<std::uint32_t> order = {11, 5, 0, 8, 8, 2, 10};
  storage.gather(order.data(), order.size(), backend::Serial{});
  const ParticleView<float> v = storage.view();
  for (std::size_t i = 0; i < order.size(); ++i) {
    EXPECT_EQ(v.x[0][i], tag(0, order[i]));
    EXPECT_EQ(v.F[8][i], tag(6 + 8, order[i]));
    EXPECT_EQ(v.vol0[i], tag(reals - 1, order[i]));
    EXPECT_EQ(v.id[i], 7 + order[i]);
    EXPECT_EQ(v.load[i], 100 + order[i]);
  }
}

}  // namespace
}  // namespace firn
