// The sparse background grid: 4x4x4 node blocks allocated only where particles are. A dense map
// over the domain's block box (4 bytes per 64 nodes) finds a block's storage slot; node data is
// stored only for active blocks, so time and memory follow the occupied region.
#pragma once

#include <cstddef>
#include <cstdint>

#include "engine/aligned_vector.hpp"
#include "engine/block_compaction.hpp"
#include "kernels/backend/schedule.hpp"
#include "kernels/block_lists.hpp"
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

  // Activates blocks b + {0,1}^3 of every particle block b (`occupied`: a flag per block of the
  // same box) and zeroes them, by compaction on the backend (kernels/block_lists.hpp). Slots are
  // numbered in increasing block id, so the layout depends only on where the particles are.
  template <class Backend>
  void activate(const std::uint8_t* occupied, const Backend& backend) {
    const ActiveBlock active{occupied, box()};
    const std::size_t count = compaction_.count(map_.size(), active, backend)[1];
    slots_.resize(count);
    coords_.resize(count * 3);
    compaction_.write(ActiveBlockSlots{map_.data(), slots_.data(), coords_.data(), box()}, backend);
    data_.resize(count * std::size_t(channels_) * kBlockNodes);
    clear(backend);
  }

  // Zeroes every channel of the active blocks.
  template <class Backend>
  void clear(const Backend& backend) {
    const std::size_t per_block = std::size_t(channels_) * kBlockNodes;
    T* data = data_.data();
    backend.parallel_for("grid.clear", slots_.size(), [=] FIRN_HD_LAMBDA(std::size_t s) {
      for (std::size_t i = 0; i < per_block; ++i) data[s * per_block + i] = T(0);
    }, backend::Schedule::blocks);
  }

  SparseGridView<T> view() {
    return SparseGridView<T>{data_.data(), channels_, map_.data(), box()};
  }
  GridSlotsView<T> slots() { return GridSlotsView<T>{data_.data(), coords_.data(), channels_}; }
  const int* slot_coords(std::size_t s) const { return coords_.data() + 3 * s; }
  const std::int32_t* block_map() const { return map_.data(); }  // block id -> slot, -1 when inactive
  BlockBox box() const { return BlockBox{{blocks_[0], blocks_[1], blocks_[2]}}; }

 private:
  GridGeometry<T> geometry_{};
  int channels_ = 0;
  int blocks_[3] = {0, 0, 0};
  AlignedVector<std::int32_t> map_;     // block id -> slot, -1 when inactive
  AlignedVector<std::uint32_t> slots_;  // slot -> block id
  AlignedVector<int> coords_;           // slot -> block coordinates
  AlignedVector<T> data_;               // slot-major, then channel, then local node
  BlockCompaction<1> compaction_{{"grid.activate.count", "grid.activate.prefix", "grid.activate.write"}};
};

}  // namespace firn
