// Simulation::remove_particles: the particles the predicate takes are gone, the others keep their
// material and their state, and all but as many as were removed keep their place (a removal moves
// only the particles that fill its holes; issue 15).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "engine/particle_fill.hpp"
#include "engine/simulation.hpp"
#include "kernels/backend/openmp.hpp"

namespace firn {
namespace {

TEST(ParticleRemoval, KeepsTheOthersAndMovesNoMoreThanItRemoves) {
  SimulationConfig c;
  c.domain_min = {0, 0, 0};
  c.domain_max = {0.4, 0.2, 0.2};
  c.dx = 0.01;
  Simulation<float, backend::OpenMP> sim(c);
  const ElasticModuli moduli = ElasticModuli::from_E_nu(1e6, 0.3);
  const int first = sim.add_material({"first", "neo_hookean", 1000, moduli});
  const int empty = sim.add_material({"empty", "neo_hookean", 800, moduli});  // no particles, between the two
  const int second = sim.add_material({"second", "neo_hookean", 500, moduli});
  std::mt19937 random(7);  // particles in no particular order
  auto shuffled_box = [&](const Point& lo, const Point& hi) {
    std::vector<Point> points = fill_box(c.domain_min, c.dx, 2, lo, hi);
    std::shuffle(points.begin(), points.end(), random);
    return points;
  };
  const double h = c.dx / 2, volume = h * h * h;
  sim.add_particles(first, shuffled_box({0.05, 0.05, 0.05}, {0.35, 0.10, 0.15}), {1, 0, 0}, volume);
  sim.add_particles(second, shuffled_box({0.05, 0.10, 0.05}, {0.35, 0.17, 0.15}), {0, 2, 0}, volume);
  sim.prepare();
  {  // values of every particle's own in a column of each group of four that a move copies
    const ParticleView<float> pv = sim.particles();
    for (std::size_t p = 0; p < pv.n; ++p) {
      pv.v[1][p] = float(pv.id[p]);
      pv.F[8][p] = 2.0f * float(pv.id[p]);
      pv.vol0[p] = 3.0f * float(pv.id[p]);
    }
  }

  // Removes what `doomed` takes and checks the survivors: each once, in its material, with its state,
  // and all but at most twice as many as were removed at their index (with two materials: the
  // holes, at most as many as removed, and the second material's shift into the gap the first
  // left, at most as many again).
  auto remove_and_check = [&](auto doomed) {
    struct Before {
      int material;
      std::size_t index;
      std::array<float, 3> x;
    };
    std::map<std::uint64_t, Before> before;
    ParticleView<float> pv = sim.particles();
    const std::size_t n = pv.n;
    for (int m : {first, second})
      for (std::size_t p = sim.material_range(m).begin; p < sim.material_range(m).end; ++p)
        before[pv.id[p]] = {m, p, {pv.x[0][p], pv.x[1][p], pv.x[2][p]}};
    std::size_t expected = 0;
    for (std::size_t p = 0; p < n; ++p) expected += doomed(pv, p);
    const std::size_t removed = sim.remove_particles(doomed);
    EXPECT_EQ(removed, expected);
    ASSERT_GT(removed, 0u);

    pv = sim.particles();
    ASSERT_EQ(pv.n, n - removed);
    std::set<std::uint64_t> kept;
    for (std::size_t p = 0; p < pv.n; ++p) kept.insert(pv.id[p]);
    EXPECT_EQ(kept.size(), pv.n);
    std::size_t next = 0, moved = 0;
    for (int m : {first, empty, second}) {
      const ParticleRange r = sim.material_range(m);
      EXPECT_EQ(r.begin, next);
      next = r.end;
      for (std::size_t p = r.begin; p < r.end; ++p) {
        const Before& b = before.at(pv.id[p]);
        EXPECT_EQ(b.material, m);
        for (int d = 0; d < 3; ++d) EXPECT_EQ(pv.x[d][p], b.x[d]);
        EXPECT_EQ(pv.v[1][p], float(pv.id[p]));
        EXPECT_EQ(pv.F[8][p], 2.0f * float(pv.id[p]));
        EXPECT_EQ(pv.vol0[p], 3.0f * float(pv.id[p]));
        moved += b.index != p;
      }
    }
    EXPECT_EQ(next, pv.n);
    EXPECT_GT(moved, 0u);
    EXPECT_LE(moved, 2 * removed);
  };
  const float cut = 0.08f;  // a slab of both materials, a tenth of each
  remove_and_check([=] FIRN_HD_LAMBDA(const ParticleView<float>& v, std::size_t p) { return v.x[0][p] < cut; });
  // All of the first material, fewer particles than the second has: the second's last ones move
  // into its place.
  remove_and_check([=] FIRN_HD_LAMBDA(const ParticleView<float>& v, std::size_t p) { return v.x[1][p] < 0.1f; });
  EXPECT_EQ(sim.material_range(first).end, 0u);
  EXPECT_GT(sim.material_range(second).end, 0u);
}

}  // namespace
}  // namespace firn
