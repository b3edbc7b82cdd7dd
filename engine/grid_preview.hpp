// The grid a simulation's next step will work on, found without stepping: the step's own binning
// (ParticleBinning) and block activation (SparseGrid) run on a scratch grid configured like the
// simulation's, so `firn check` reports the engine's figures for grid size and memory.
#pragma once

#include <cstddef>
#include <vector>

#include "engine/particle_binning.hpp"
#include "engine/simulation.hpp"
#include "engine/sparse_grid.hpp"
#include "kernels/shape_functions.hpp"

namespace firn {

struct GridPreview {
  int cells[3] = {0, 0, 0};        // grid cells per axis (nodes - 1)
  std::size_t active_blocks = 0;   // 4^3-node blocks the step activates
  std::size_t grid_bytes = 0;      // the sparse grid with those blocks active
  std::size_t particle_bytes = 0;  // every allocated particle column, and the binning's arrays
};

template <class T, class Backend>
GridPreview preview_grid(Simulation<T, Backend>& sim) {
  // The binning's keys, order and bucket counts: about three words a particle.
  constexpr std::size_t kBinningBytesPerParticle = 12;
  const SparseGrid<T>& grid = sim.grid();
  SparseGrid<T> scratch;
  scratch.configure(grid.geometry(), grid.channels());
  std::vector<ParticleRange> ranges;
  for (std::size_t m = 0; m < sim.material_count(); ++m) ranges.push_back(sim.material_range(int(m)));
  ParticleBinning binning;
  if (sim.config().shape == Shape::quadratic)
    binning.compute_keys<QuadraticBSpline<T>>(sim.particles(), ranges, scratch.geometry(), scratch.blocks(),
                                              sim.backend());
  else
    binning.compute_keys<CubicBSpline<T>>(sim.particles(), ranges, scratch.geometry(), scratch.blocks(), sim.backend());
  binning.sort(scratch.blocks(), sim.backend());
  scratch.activate(binning.occupied_blocks(), sim.backend());

  GridPreview p;
  for (int d = 0; d < 3; ++d) p.cells[d] = grid.geometry().nodes[d] - 1;
  p.active_blocks = scratch.active_count();
  p.grid_bytes = scratch.memory_bytes();
  p.particle_bytes = sim.particle_count() * (sim.bytes_per_particle() + kBinningBytesPerParticle);
  return p;
}

}  // namespace firn
