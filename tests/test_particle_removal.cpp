// Simulation::remove_particles: the particles the predicate takes are gone, the others keep their
// material and their state, and within each material they come in block order, the order the step's
// binning sorts them in (the removal's gather is also a reorder; issue 15).
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
#include "kernels/shape_functions.hpp"

namespace firn {
namespace {

TEST(ParticleRemoval, KeepsTheOthersInBlockOrderWithinEachMaterial) {
  SimulationConfig c;
  c.domain_min = {0, 0, 0};
  c.domain_max = {0.4, 0.2, 0.2};
  c.dx = 0.01;
  Simulation<float, backend::OpenMP> sim(c);
  const ElasticModuli moduli = ElasticModuli::from_E_nu(1e6, 0.3);
  const int first = sim.add_material({"first", "neo_hookean", 1000, moduli});
  // A material without particles between the two: the binning's buckets count only the others.
  const int empty = sim.add_material({"empty", "neo_hookean", 800, moduli});
  const int second = sim.add_material({"second", "neo_hookean", 500, moduli});
  // Each material's particles added in a shuffled order, so that neither is in block order before.
  std::mt19937 random(7);
  auto shuffled_box = [&](const Point& lo, const Point& hi) {
    std::vector<Point> points = fill_box(c.domain_min, c.dx, 2, lo, hi);
    std::shuffle(points.begin(), points.end(), random);
    return points;
  };
  const double h = c.dx / 2, volume = h * h * h;
  sim.add_particles(first, shuffled_box({0.05, 0.05, 0.05}, {0.35, 0.10, 0.15}), {1, 0, 0}, volume);
  sim.add_particles(second, shuffled_box({0.05, 0.10, 0.05}, {0.35, 0.15, 0.15}), {0, 2, 0}, volume);
  sim.prepare();

  // How often the block of the particle's stencil, as the binning keys it, steps back along a
  // material's range (0: block order).
  auto steps_back = [&](int m) {
    const ParticleView<float> v = sim.particles();
    const GridGeometry<float> g = sim.grid().geometry();
    std::array<int, 3> previous{-1, -1, -1};
    std::size_t count = 0;
    for (std::size_t p = sim.material_range(m).begin; p < sim.material_range(m).end; ++p) {
      std::array<int, 3> block;
      for (int d = 0; d < 3; ++d)
        block[d] = QuadraticBSpline<float>::base((v.x[d][p] - g.origin[d]) * g.inv_dx) >> kBlockShift;
      count += block < previous;
      previous = block;
    }
    return count;
  };
  ASSERT_GT(steps_back(first), 0u);
  ASSERT_GT(steps_back(second), 0u);

  // Each particle's material and position by its id, before.
  struct Before {
    int material;
    std::array<float, 3> x;
  };
  std::map<std::uint64_t, Before> before;
  ParticleView<float> pv = sim.particles();
  const std::size_t n = pv.n;
  for (int m : {first, second})
    for (std::size_t p = sim.material_range(m).begin; p < sim.material_range(m).end; ++p)
      before[pv.id[p]] = {m, {pv.x[0][p], pv.x[1][p], pv.x[2][p]}};

  const float cut = 0.2f;  // removes x < cut
  std::size_t expected = 0;
  for (std::size_t p = 0; p < n; ++p) expected += pv.x[0][p] < cut;
  const std::size_t removed =
      sim.remove_particles([=] FIRN_HD_LAMBDA(const ParticleView<float>& v, std::size_t p) { return v.x[0][p] < cut; });
  EXPECT_EQ(removed, expected);
  ASSERT_GT(removed, 0u);

  pv = sim.particles();
  ASSERT_EQ(pv.n, n - removed);
  std::set<std::uint64_t> kept;  // each survivor once
  for (std::size_t p = 0; p < pv.n; ++p) kept.insert(pv.id[p]);
  EXPECT_EQ(kept.size(), pv.n);
  std::size_t next = 0;
  for (int m : {first, empty, second}) {
    const ParticleRange r = sim.material_range(m);
    EXPECT_EQ(r.begin, next);
    next = r.end;
    for (std::size_t p = r.begin; p < r.end; ++p) {
      EXPECT_GE(pv.x[0][p], cut);
      const Before& b = before.at(pv.id[p]);
      EXPECT_EQ(b.material, m);
      for (int d = 0; d < 3; ++d) EXPECT_EQ(pv.x[d][p], b.x[d]);
    }
    EXPECT_EQ(steps_back(m), 0u) << "material " << m << " is not in block order";
  }
  EXPECT_EQ(next, pv.n);
}

}  // namespace
}  // namespace firn
