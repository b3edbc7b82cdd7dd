// The step's P2G (kernels/p2g.hpp for one particle) as a block scatter: the particles binned to
// grid block b (every non-empty material's bucket, in sorted order) add their contributions to a
// dense scratch over the block's window (kBlockSize + support - 1 nodes per axis), which is then
// added to the sparse grid. Blocks of one parity colour never share a node, so a backend runs them
// concurrently, colour after colour (kernels/backend/block_colouring.hpp).
//
// The two ways a backend launches it:
//   scatter(b)               a whole block on one thread, its scratch on the stack (CPU backends);
//   scatter.particle(s, t)   the contributions of the particle at sorted position s into target t
//                            (t.add(i, j, k, values[kChannels]), nodes in stencil order), with
//                            Scratch, grid and bins for a backend that shares a block's particles
//                            and its scratch among threads (the CUDA backend).
// A scatter functor may also have `bool keeps(b) const`: the blocks it leaves out are not scattered
// on any backend (kernels/backend/scatter_skip.hpp).
#pragma once

#include <cstdint>

#include "kernels/binning_view.hpp"
#include "kernels/block_window.hpp"
#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"
#include "kernels/p2g.hpp"
#include "kernels/particle_attributes.hpp"
#include "kernels/transfer.hpp"

namespace firn {

// A whole block of a scatter on one thread: every particle binned to block b (in its buckets'
// sorted order) adds into a scratch over the block's window, which is then added to the grid.
template <class Scatter>
FIRN_HD void scatter_block(const Scatter& scatter, std::uint32_t b) {
  int block[3];
  scatter.grid.box.coords(b, block);
  typename Scatter::Scratch scratch;
  scratch.reset(block);
  for (std::size_t m = 0; m < scatter.bins.material_count; ++m)
    for (std::uint32_t s = scatter.bins.bucket_begin(m, b), e = scatter.bins.bucket_end(m, b); s < e; ++s)
      scatter.particle(s, scratch);
  scratch.flush(scatter.grid);
}

template <class T, class ShapeT, Transfer kTransfer>
struct P2GScatter {
  static constexpr int kSupport = ShapeT::kSupport;
  static constexpr int kSpan = kBlockSize + kSupport - 1;
  static constexpr int kChannels = GridChannels<kTransfer>::kCount;
  using Value = T;
  using Scratch = BlockScratch<T, kSpan, kChannels>;

  ParticleView<T> pv;
  SparseGridView<T> grid;
  BinningView bins;
  GridGeometry<T> g;
  T dt;

  template <class Target>
  FIRN_HD void particle(std::uint32_t s, Target& out) const {
    p2g_particle<T, ShapeT, kTransfer>(pv, bins.order[s], g, dt, out);
  }

  FIRN_HD void operator()(std::uint32_t b) const { scatter_block(*this, b); }
};

}  // namespace firn
