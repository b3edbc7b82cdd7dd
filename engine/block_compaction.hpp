// Runs the block compaction of kernels/block_compaction.hpp with a backend: count() launches the
// count and the prefix and returns the classes' begins (the values the host reads), the caller
// sizes its lists, then write() launches the write. The scratch (chunk counts, the blocks' classes)
// is kept between steps.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "engine/aligned_vector.hpp"
#include "kernels/backend/schedule.hpp"
#include "kernels/block_compaction.hpp"

namespace firn {

// The launches' names in a profile.
struct CompactionNames {
  const char* count;
  const char* prefix;
  const char* write;
};

template <int kClasses>
class BlockCompaction {
 public:
  explicit BlockCompaction(CompactionNames names) : names_(names) {}

  // Classifies blocks [0, n); returns begins[k], the first position of class k in the class-grouped
  // list (begins[kClasses]: the number of selected blocks).
  template <class Classify, class Backend>
  std::array<std::uint32_t, kClasses + 1> count(std::size_t n, const Classify& classify, const Backend& backend) {
    n_ = n;
    chunks_ = compaction_chunks(n);
    scratch_.resize(chunks_ * kClasses + kClasses + 1);
    classes_.resize(n);
    std::uint32_t* counts = scratch_.data();
    backend.parallel_for(names_.count, chunks_, CompactionCount<kClasses, Classify>{classify, n, counts, classes_.data()},
                         schedule());
    backend.parallel_for(names_.prefix, 1, CompactionPrefix<kClasses>{chunks_, counts, begins()});
    std::array<std::uint32_t, kClasses + 1> out;
    for (int k = 0; k <= kClasses; ++k) out[std::size_t(k)] = begins()[k];
    return out;
  }

  // Emits every block of the last count() to `emit`.
  template <class Emit, class Backend>
  void write(const Emit& emit, const Backend& backend) {
    backend.parallel_for(names_.write, chunks_,
                         CompactionWrite<kClasses, Emit>{emit, n_, classes_.data(), scratch_.data(), begins()},
                         schedule());
  }

 private:
  // The chunks (kCompactionChunk items each) on every thread where there are many: a conveyor's
  // removal over tire_on_snow's 930,664 particles (3,636 chunks) ran on one thread as uniform
  // items (its count 0.49 ms per step, 0.25 on two threads); the grid's compactions over its
  // blocks (tens of chunks of a cheap test) stay on one, where a team costs more than it saves
  // (tire_on_snow: 0.23 ms per step in all, 0.28 on two threads).
  static constexpr std::size_t kParallelChunks = 1024;
  backend::Schedule schedule() const {
    return chunks_ >= kParallelChunks ? backend::Schedule::blocks : backend::Schedule::uniform;
  }

  std::uint32_t* begins() { return scratch_.data() + chunks_ * kClasses; }

  CompactionNames names_;
  std::size_t n_ = 0, chunks_ = 0;
  AlignedVector<std::uint32_t> scratch_;  // [chunk][kClasses] counts, then offsets; then the begins
  AlignedVector<std::int8_t> classes_;    // [b]: the block's class, -1 when left out
};

}  // namespace firn
