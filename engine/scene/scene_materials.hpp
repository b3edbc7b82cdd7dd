// The engine's materials for a scene's [materials.NAME] tables. A uniform table is one engine
// material; a varied one (`vary`, engine/scene/material_variation.hpp) is `levels` consecutive
// engine materials NAME~0 ... NAME~(levels - 1), and each of its particles goes to the level of
// the table's noise at the particle's rest position. A scene without `vary` gets its tables as
// they are, in order, with its particles in the order given: it pays nothing (no noise is
// evaluated) and its runs are bit for bit what they were.
#pragma once

#include <cstddef>
#include <numeric>
#include <optional>
#include <vector>

#include "engine/noise_field.hpp"
#include "engine/scene/scene.hpp"
#include "engine/simulation.hpp"

namespace firn {

class SceneMaterials {
 public:
  explicit SceneMaterials(const SceneSpec& scene);

  const std::vector<MaterialInfo>& engine() const { return engine_; }  // in engine index order
  int table_of(int engine_material) const { return table_of_[std::size_t(engine_material)]; }
  bool varied(int table) const { return noise_[std::size_t(table)].has_value(); }
  int first(int table) const { return first_[std::size_t(table)]; }  // its first engine material
  int count(int table) const { return count_[std::size_t(table)]; }  // its engine materials
  // The engine material of each rest position of a particle of `table`.
  std::vector<int> materials_at(int table, const std::vector<Point>& rest) const;

 private:
  std::vector<MaterialInfo> engine_;
  std::vector<int> table_of_, first_, count_;
  std::vector<std::optional<NoiseField>> noise_;
};

// Adds particles of scene table `table` to `sim`: particle i at positions[i] with velocities[i],
// in the engine material of its level at rest position rest[i] (a body's lattice site; for the
// conveyor, where the undisturbed ground carried the particle from at t = 0, so the noise moves
// with the snow). Particles are added grouped by engine material, in their order within each;
// the return value says the order: the k-th particle added is input index order[k].
template <class T, class Backend>
std::vector<std::size_t> add_table_particles(Simulation<T, Backend>& sim, const SceneMaterials& materials, int table,
                                             const std::vector<Point>& rest, const std::vector<Point>& positions,
                                             const std::vector<Point>& velocities, double volume) {
  std::vector<std::size_t> order(positions.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  if (!materials.varied(table)) {
    sim.add_particles(materials.first(table), positions, velocities, volume);
    return order;
  }
  // A stable counting sort of the particles by level: one pass, whatever the number of levels.
  const std::vector<int> material = materials.materials_at(table, rest);
  const int first = materials.first(table), count = materials.count(table);
  std::vector<std::size_t> start(std::size_t(count) + 1, 0);
  for (int m : material) ++start[std::size_t(m - first) + 1];
  for (int l = 0; l < count; ++l) start[std::size_t(l) + 1] += start[std::size_t(l)];
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < positions.size(); ++i) order[next[std::size_t(material[i] - first)]++] = i;
  for (int l = 0; l < count; ++l) {
    if (start[std::size_t(l)] == start[std::size_t(l) + 1]) continue;
    std::vector<Point> x, v;
    for (std::size_t k = start[std::size_t(l)]; k < start[std::size_t(l) + 1]; ++k) {
      x.push_back(positions[order[k]]);
      v.push_back(velocities[order[k]]);
    }
    sim.add_particles(first + l, x, v, volume);
  }
  return order;
}

}  // namespace firn
