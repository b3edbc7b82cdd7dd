// The sparse background grid: 4x4x4 node blocks allocated only where particles are. A dense map
// over the domain's block box (4 bytes per 64 nodes) finds a block's storage slot; node data is
// stored only for active blocks, so time and memory follow the occupied region.
#pragma once

#include <cstddef>
#include <cstdint>

#include "engine/aligned_vector.hpp"
#include "kernels/block_window.hpp"
#include "kernels/grid_geometry.hpp"
#include "kernels/grid_slots.hpp"
#include "kernels/hd.hpp"

namespace firn {

template <class T>
class SparseGrid {
 public:
  void configure(const GridGeometry<T>& geometry, int channels) {
    geometry_ = geometry;
    channels_ = channels;
    // A particle block b writes blocks b and b + 1, so one spare block per axis.
    for (int d = 0; d < 3; ++d) blocks_[d] = ((geometry.nodes[d] - 1) >> kBlockShift) + 2;
    map_.assign(std::size_t(blocks_[0]) * blocks_[1] * blocks_[2], -1);
    slots_.clear();
  }

  const GridGeometry<T>& geometry() const { return geometry_; }
  const int* blocks() const { return blocks_; }
  std::size_t block_count() const { return map_.size(); }
  std::size_t active_count() const { return slots_.size(); }
  int channels() const { return channels_; }
  std::size_t memory_bytes() const {
    return map_.capacity() * sizeof(std::int32_t) + data_.capacity() * sizeof(T) +
           slots_.capacity() * sizeof(std::uint32_t) + coords_.capacity() * sizeof(int);
  }

  // Activates blocks b + {0,1}^3 of every particle block (ids in increasing order) and zeroes them.
  // Slots are numbered in that order, so the layout does not depend on the thread count.
  template <class Backend>
  void activate(const AlignedVector<std::uint32_t>& particle_blocks, const Backend& backend) {
    for (std::uint32_t id : slots_) map_[id] = -1;
    slots_.clear();
    const int syz = blocks_[1] * blocks_[2];
    for (std::uint32_t id : particle_blocks) {
      const int bx = int(id) / syz, by = (int(id) / blocks_[2]) % blocks_[1], bz = int(id) % blocks_[2];
      for (int o = 0; o < 8; ++o) {
        const std::uint32_t nb = std::uint32_t(((bx + (o >> 2)) * blocks_[1] + by + ((o >> 1) & 1)) * blocks_[2] + bz + (o & 1));
        if (map_[nb] < 0) {
          map_[nb] = std::int32_t(slots_.size());
          slots_.push_back(nb);
        }
      }
    }
    coords_.resize(slots_.size() * 3);
    for (std::size_t s = 0; s < slots_.size(); ++s) {
      const int id = int(slots_[s]);
      coords_[3 * s] = id / syz;
      coords_[3 * s + 1] = (id / blocks_[2]) % blocks_[1];
      coords_[3 * s + 2] = id % blocks_[2];
    }
    data_.resize(slots_.size() * std::size_t(channels_) * kBlockNodes);
    clear(backend);
  }

  // Zeroes every channel of the active blocks.
  template <class Backend>
  void clear(const Backend& backend) {
    const std::size_t per_block = std::size_t(channels_) * kBlockNodes;
    T* data = data_.data();
    backend.parallel_for("grid.clear", slots_.size(), [=] FIRN_HD_LAMBDA(std::size_t s) {
      for (std::size_t i = 0; i < per_block; ++i) data[s * per_block + i] = T(0);
    });
  }

  SparseGridView<T> view() {
    return SparseGridView<T>{data_.data(), channels_, map_.data(), {blocks_[0], blocks_[1], blocks_[2]}};
  }
  GridSlotsView<T> slots() { return GridSlotsView<T>{data_.data(), coords_.data(), channels_}; }
  const int* slot_coords(std::size_t s) const { return coords_.data() + 3 * s; }

 private:
  GridGeometry<T> geometry_{};
  int channels_ = 0;
  int blocks_[3] = {0, 0, 0};
  AlignedVector<std::int32_t> map_;     // block id -> slot, -1 when inactive
  AlignedVector<std::uint32_t> slots_;  // slot -> block id
  AlignedVector<int> coords_;           // slot -> block coordinates
  AlignedVector<T> data_;               // slot-major, then channel, then local node
};

}  // namespace firn
