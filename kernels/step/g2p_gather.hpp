// The step's G2P (kernels/g2p.hpp for one particle) with the stability guard, as a block gather:
// the grid velocities over block b's window are copied into a dense window, then every particle
// binned to b reads it, updates itself and adds its check to the block's GuardSummary.
//
// The two ways a backend launches it:
//   gather(b)                        a whole block on one thread, returning its summary (CPU);
//   window.load_node(grid, kFirstChannel, n) for the window's nodes, then
//   gather.particle(s, window, acc)  for the particles at sorted positions s, with Window, grid and
//                                    bins for a backend that shares a block among threads (CUDA).
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernels/binning_view.hpp"
#include "kernels/block_window.hpp"
#include "kernels/g2p.hpp"
#include "kernels/grid_geometry.hpp"
#include "kernels/guard_summary.hpp"
#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"
#include "kernels/transfer.hpp"

namespace firn {

template <class T, class ShapeT, Transfer kTransfer>
struct G2PGather {
  static constexpr int kSpan = kBlockSize + ShapeT::kSupport - 1;
  static constexpr int kFirstChannel = GridChannels<kTransfer>::kVelocity;
  using Window = BlockGather<T, kSpan, GridChannels<kTransfer>::kGatherCount>;
  using Result = GuardSummary<T>;

  ParticleView<T> pv;
  SparseGridView<T> grid;
  BinningView bins;
  GridGeometry<T> g;
  T dt;
  T flip_alpha;

  FIRN_HD void particle(std::uint32_t s, const Window& window, GuardSummary<T>& acc) const {
    const std::size_t p = bins.order[s];
    const ParticleCheck<T> c = g2p_particle<T, ShapeT, kTransfer>(pv, p, g, dt, flip_alpha, window);
    acc.add(p, c.speed, c.J, c.moved, g.dx);
  }

  FIRN_HD GuardSummary<T> operator()(std::uint32_t b) const {
    int block[3];
    grid.box.coords(b, block);
    Window window;
    window.load(grid, kFirstChannel, block);
    GuardSummary<T> summary;
    for (std::size_t m = 0; m < bins.material_count; ++m)
      for (std::uint32_t s = bins.bucket_begin(m, b), e = bins.bucket_end(m, b); s < e; ++s)
        particle(s, window, summary);
    return summary;
  }
};

}  // namespace firn
