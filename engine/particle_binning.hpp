// Bins particles by (material, grid block of their stencil base node) with a stable counting
// sort, so that P2G and G2P can walk the particles block by block (DESIGN.md section 2, rule 7).
// Only materials that have particles get buckets: the sort's cost grows with materials x blocks, so
// a material declared but absent would cost as much as one present (docs/performance.md).
// The sort is stable on the physical index, so its result is unique and independent of the thread
// count. The particle arrays themselves are reordered only when the walk has become scattered
// (see needs_reorder), since most steps move few particles across a block boundary.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "engine/aligned_vector.hpp"
#include "engine/block_compaction.hpp"
#include "kernels/backend/block_colouring.hpp"
#include "kernels/backend/schedule.hpp"
#include "kernels/binning_view.hpp"
#include "kernels/block_box.hpp"
#include "kernels/block_lists.hpp"
#include "kernels/combine.hpp"
#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn {

struct ParticleRange {
  std::size_t begin, end;
};

class ParticleBinning {
 public:
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

  // Computes every particle's key; returns the first particle whose stencil leaves the grid (or
  // that is not finite), or kNone. `materials` are the contiguous material ranges; bucket index m
  // counts only the non-empty ones.
  template <class ShapeT, class T, class Backend>
  std::size_t compute_keys(const ParticleView<T>& pv, const std::vector<ParticleRange>& materials,
                           const GridGeometry<T>& g, const int blocks[3], const Backend& backend) {
    keys_.resize(pv.n);
    block_count_ = std::size_t(blocks[0]) * blocks[1] * blocks[2];
    material_count_ = 0;
    std::uint32_t* keys = keys_.data();
    std::size_t first_bad = kNone;
    // Bounds in cell units as T and strides as size_t: no value the loop reads can alias the
    // uint32 keys it stores (an int would), so the compiler keeps them all in registers.
    const T origin[3] = {g.origin[0], g.origin[1], g.origin[2]}, inv_dx = g.inv_dx;
    T limit[3];
    for (int d = 0; d < 3; ++d) limit[d] = T(g.nodes[d] - ShapeT::kSupport + 1);
    const BlockBox box{{blocks[0], blocks[1], blocks[2]}};
    const std::size_t stride_x = std::size_t(box.stride(0)), stride_y = std::size_t(box.stride(1)),
                      stride_z = std::size_t(box.stride(2));
    const T* const x[3] = {pv.x[0], pv.x[1], pv.x[2]};
    // Particle p along axis d in cells from where its stencil starts (its base node is int(s)).
    const auto cell = [=] FIRN_HD_LAMBDA(std::size_t p, int d) {
      return (x[d][p] - origin[d]) * inv_dx - ShapeT::kOffset;
    };
    for (std::size_t m = 0; m < materials.size(); ++m) {
      if (materials[m].end == materials[m].begin) continue;
      const std::size_t begin = materials[m].begin, n = materials[m].end - begin;
      const std::size_t key0 = material_count_++ * block_count_;
      // The keys in 32-bit arithmetic with no branch, and whether any particle is outside, ORed: a
      // loop the compiler vectorises across particles (issue 15). An axis outside adds block 0
      // along it, the key of some block of the grid, which only a grid preview sorts.
      const std::uint64_t any_outside = backend.parallel_reduce(
          "bin.keys", n, std::uint64_t(0),
          [=] FIRN_HD_LAMBDA(std::size_t i, std::uint64_t& acc) {
            const std::size_t p = begin + i;
            std::uint32_t key = std::uint32_t(key0), inside = 1;
            for (int d = 0; d < 3; ++d) {
              const T s = cell(p, d);
              const std::uint32_t in = (s >= T(0)) & (s < limit[d]);  // false for NaN
              const std::uint32_t b = in ? std::uint32_t(int(s) >> kBlockShift) : 0u;
              key += b * std::uint32_t(d == 0 ? stride_x : d == 1 ? stride_y : stride_z);
              inside &= in;
            }
            keys[p] = key;
            acc |= inside ^ 1u;  // a 64-bit flag, which the 32-bit keys cannot alias
          },
          BitOr{});
      if (!any_outside) continue;
      // Then the first particle outside, in a run that is about to stop.
      const std::size_t bad = backend.parallel_reduce(
          "bin.outside", n, kNone,
          [=] FIRN_HD_LAMBDA(std::size_t i, std::size_t& acc) {
            const std::size_t p = begin + i;
            bool inside = true;
            for (int d = 0; d < 3; ++d) {
              const T s = cell(p, d);
              inside = inside && s >= T(0) && s < limit[d];
            }
            if (!inside && p < acc) acc = p;
          },
          Min{});
      if (bad < first_bad) first_bad = bad;
    }
    return first_bad;
  }

  // Stable sort of the keys (on the device where the backend brings its own sort), then the
  // particle blocks and their colouring.
  template <class Backend>
  void sort(const int blocks[3], const Backend& backend) {
    const std::size_t n = keys_.size(), K = material_count_ * block_count_;
    if constexpr (sorts_on_device<Backend>(0)) {
      order_.resize(n);
      bucket_begin_.resize(K + 1);
      backend.sort_into_buckets(keys_.data(), n, K, order_.data(), bucket_begin_.data());
    } else {
      counting_sort(n, K, backend);
    }
    collect_blocks(blocks, backend);
  }

  // The CPU's stable counting sort in backend.threads() parts: order and bucket ranges (public, as
  // nvcc's extended lambdas cannot sit in private members).
  template <class Backend>
  void counting_sort(std::size_t n, std::size_t K, const Backend& backend) {
    const std::size_t parts = std::size_t(backend.threads());
    counts_.resize(parts * K);
    const std::uint32_t* keys = keys_.data();
    std::uint32_t* counts = counts_.data();
    // Part t zeroes its counts (on its thread, rather than all of them on the host first), then
    // counts particles [t n / parts, (t + 1) n / parts), a run of equal keys at a time: the
    // arrays are in block order since the last reorder, so runs are long, and a count kept in a
    // register spares an increment in memory that waits on the one before it (issue 15).
    backend.parallel_for("bin.count", parts, [=] FIRN_HD_LAMBDA(std::size_t t) {
      for (std::size_t k = 0; k < K; ++k) counts[t * K + k] = 0;
      const std::size_t end = (t + 1) * n / parts;
      for (std::size_t p = t * n / parts; p < end;) {
        const std::uint32_t key = keys[p];
        const std::size_t run = p;
        while (++p < end && keys[p] == key) {
        }
        counts[t * K + key] += std::uint32_t(p - run);
      }
    }, backend::Schedule::parts);
    // Exclusive prefix, bucket-major then part: part t's particles of bucket k follow part t-1's.
    // Most buckets are empty (K covers every block of the grid's box for every material: the
    // snowball pair's 1,100 occupied blocks of 34,200, three times), and no particle reads an
    // empty bucket's cursors, so those are left as they are.
    bucket_begin_.resize(K + 1);
    std::uint32_t* begin = bucket_begin_.data();
    std::uint32_t running = 0;
    for (std::size_t k = 0; k < K; ++k) {
      begin[k] = running;
      std::uint32_t any = 0;
      for (std::size_t t = 0; t < parts; ++t) any |= counts[t * K + k];
      if (any == 0) continue;
      for (std::size_t t = 0; t < parts; ++t) {
        const std::uint32_t c = counts[t * K + k];
        counts[t * K + k] = running;
        running += c;
      }
    }
    begin[K] = running;
    order_.resize(n);
    std::uint32_t* order = order_.data();
    // The same runs: a run's positions follow each other from its bucket's cursor.
    backend.parallel_for("bin.scatter", parts, [=] FIRN_HD_LAMBDA(std::size_t t) {
      const std::size_t end = (t + 1) * n / parts;
      for (std::size_t p = t * n / parts; p < end;) {
        const std::uint32_t key = keys[p];
        std::uint32_t cursor = counts[t * K + key];
        do order[cursor++] = std::uint32_t(p);
        while (++p < end && keys[p] == key);
        counts[t * K + key] = cursor;
      }
    }, backend::Schedule::parts);
  }

  // Whether reordering the particle arrays pays now; called once per step, after sort(). Walking
  // the arrays in block order costs about kBreakCost per break in the order (P2G and G2P each read
  // a part-used cache line of every column there), every step until the arrays are reordered;
  // reordering (ParticleStorage::gather) costs about kReorderCost per particle. So reorder once the
  // breaks summed over the steps since the last reorder have cost as much as one reorder: the
  // rent-or-buy rule (Karlin, Manasse, Rudolph and Sleator 1988, "Competitive snoopy caching",
  // Algorithmica 3), which for breaks that grow linearly with the steps is the reorder interval of
  // least cost per step. A scene whose particles cross blocks fast (snowball_pair) reorders every
  // few steps, a slow one (cube_drop) every few tens.
  template <class Backend>
  bool needs_reorder(const Backend& backend) {
    // From cube_drop and snowball_pair (AMD EPYC Zen 5, 2 threads, 26 float columns): the gather
    // took 12-13 ns per particle; reordering cube_drop at one break per 16 particles instead of
    // 64 made P2G + G2P 1.4 ms per step slower, for an estimated 12,000 more breaks on average.
    static constexpr double kReorderCost = 12, kBreakCost = 115;
    const std::uint32_t* order = order_.data();
    const std::size_t n = order_.size();
    if (n < 2) return false;
    walk_breaks_ += backend.parallel_reduce(
        "bin.breaks", n - 1, std::size_t(0),
        [=] FIRN_HD_LAMBDA(std::size_t i, std::size_t& acc) { acc += order[i + 1] != order[i] + 1; }, Sum{});
    return double(walk_breaks_) * kBreakCost >= double(n) * kReorderCost;
  }

  // After the particle arrays were permuted by order(): the order is the identity.
  template <class Backend>
  void reordered(const Backend& backend) {
    std::uint32_t* order = order_.data();
    backend.parallel_for("bin.identity", order_.size(), [=] FIRN_HD_LAMBDA(std::size_t i) { order[i] = std::uint32_t(i); });
    walk_breaks_ = 0;
  }

  // The breaks summed since the last reorder: state that decides the next reorder, and with it the
  // order of the sums over particles, so checkpoints keep it (Simulation::save_state).
  std::uint64_t& walk_breaks() { return walk_breaks_; }

  const std::uint32_t* order() const { return order_.data(); }
  // The order and the buckets of sorted positions per (non-empty material, block), for kernels.
  BinningView view() const { return BinningView{order_.data(), bucket_begin_.data(), block_count_, material_count_}; }
  // Blocks holding particles, in increasing id, and the same grouped by parity colour.
  const AlignedVector<std::uint32_t>& particle_blocks() const { return particle_blocks_; }
  // Per block of the box, 1 where particles are (the grid's activation reads it).
  const std::uint8_t* occupied_blocks() const { return occupied_.data(); }
  backend::BlockColouring colouring() const {
    backend::BlockColouring c;
    c.blocks = coloured_.data();
    for (int i = 0; i <= backend::BlockColouring::kColours; ++i) c.begin[i] = colour_begin_[i];
    return c;
  }

 private:
  // Whether the backend sorts on the device (backend::Cuda::sort_into_buckets).
  template <class Backend>
  static constexpr auto sorts_on_device(int) -> decltype(&Backend::sort_into_buckets, bool()) {
    return true;
  }
  template <class Backend>
  static constexpr bool sorts_on_device(long) { return false; }

  // The blocks holding particles, in id order and by colour, and their flags, by compaction on the
  // backend (kernels/block_lists.hpp).
  template <class Backend>
  void collect_blocks(const int blocks[3], const Backend& backend) {
    const BlockBox box{{blocks[0], blocks[1], blocks[2]}};
    const ParticleBlockColour colour{bucket_begin_.data(), block_count_, material_count_, box};
    const auto begins = compaction_.count(block_count_, colour, backend);
    for (int c = 0; c <= backend::BlockColouring::kColours; ++c) colour_begin_[c] = begins[std::size_t(c)];
    const std::size_t count = begins[backend::BlockColouring::kColours];
    particle_blocks_.resize(count);
    coloured_.resize(count);
    occupied_.resize(block_count_);
    compaction_.write(ParticleBlockLists{particle_blocks_.data(), coloured_.data(), occupied_.data()}, backend);
  }

  std::size_t block_count_ = 0, material_count_ = 0;
  std::uint64_t walk_breaks_ = 0;
  AlignedVector<std::uint32_t> keys_, order_, counts_, bucket_begin_, particle_blocks_, coloured_;
  AlignedVector<std::uint8_t> occupied_;  // [block]: 1 where particles are
  BlockCompaction<backend::BlockColouring::kColours> compaction_{{"bin.blocks.count", "bin.blocks.prefix", "bin.blocks.write"}};
  std::size_t colour_begin_[backend::BlockColouring::kColours + 1] = {};
};

}  // namespace firn
