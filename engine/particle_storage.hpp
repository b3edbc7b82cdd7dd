// Owns the particle arrays: one aligned column per scalar component of every attribute in
// FIRN_PARTICLE_ATTRIBUTES. Attributes marked on_demand are allocated only when enabled.
#pragma once

#include <cstddef>
#include <cstdint>

#include "engine/aligned_vector.hpp"
#include "engine/state_stream.hpp"
#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn {

// out[c][i] = in[c][order[i]] for the first `count` of K columns: a group of columns of
// ParticleStorage::gather, which reads order[i] once for the group.
template <class S, int K>
struct GatherColumns {
  S* out[K];
  const S* in[K];
  const std::uint32_t* order;
  int count;
  FIRN_HD void operator()(std::size_t i) const {
    const std::uint32_t from = order[i];
    for (int c = 0; c < K; ++c)
      if (c < count) out[c][i] = in[c][from];
  }
};

// col[c][to[i]] = col[c][from[i]] for the first `count` of K columns: a group of columns of
// ParticleStorage::move. No `from` is also a `to`, so the moves run in any order.
template <class S, int K>
struct MoveColumns {
  S* col[K];
  const std::uint32_t* to;
  const std::uint32_t* from;
  int count;
  FIRN_HD void operator()(std::size_t i) const {
    const std::uint32_t a = to[i], b = from[i];
    for (int c = 0; c < K; ++c)
      if (c < count) col[c][a] = col[c][b];
  }
};

template <class T>
class ParticleStorage {
 public:
  ParticleStorage() {
#define FIRN_ENABLE_ALWAYS(name, n, kind, alloc, doc) enabled_[int(Attribute::name)] = is_always(#alloc);
    FIRN_PARTICLE_ATTRIBUTES(FIRN_ENABLE_ALWAYS)
#undef FIRN_ENABLE_ALWAYS
  }

  std::size_t size() const { return size_; }
  bool has(Attribute a) const { return enabled_[int(a)]; }

  // Bytes of every enabled column for one particle.
  std::size_t bytes_per_particle() const {
    std::size_t bytes = 0;
#define FIRN_COLUMN_BYTES(name, n, kind, alloc, doc) \
  bytes += has(Attribute::name) ? n * sizeof(FIRN_SCALAR_##kind(T)) : 0;
    FIRN_PARTICLE_ATTRIBUTES(FIRN_COLUMN_BYTES)
#undef FIRN_COLUMN_BYTES
    return bytes;
  }

  // Allocates an on_demand attribute, zero-filled.
  void enable(Attribute a) {
    enabled_[int(a)] = true;
    resize(size_);
  }

  // Resizes every enabled column; new entries are zero.
  void resize(std::size_t n) {
#define FIRN_RESIZE(name, n_, kind, alloc, doc) \
  for (auto& col : name##_) col.resize(has(Attribute::name) ? n : 0);
    FIRN_PARTICLE_ATTRIBUTES(FIRN_RESIZE)
#undef FIRN_RESIZE
    size_ = n;
  }

  ParticleView<T> view() {
    ParticleView<T> v;
#define FIRN_FILL_VIEW(name, n, kind, alloc, doc) assign(v.name, name##_);
    FIRN_PARTICLE_ATTRIBUTES(FIRN_FILL_VIEW)
#undef FIRN_FILL_VIEW
    v.n = size_;
    return v;
  }

  // Reorders and/or drops particles in every enabled column: new[i] = old[order[i]] for
  // i < count (count <= size), using the backend for the copies. With `stress` false the stress
  // columns tau are left as they are, out of order: for a caller that recomputes every particle's
  // stress before anything reads it (the step's reorder, before the constitutive update).
  template <class Backend>
  void gather(const std::uint32_t* order, std::size_t count, const Backend& backend, bool stress = true) {
    GatherList<T> reals;
    GatherList<std::uint32_t> indices;
    list_columns(reals, indices, stress);
    gather_columns(reals, spare_real_, order, count, backend);
    gather_columns(indices, spare_index_, order, count, backend);
    size_ = count;
  }

  // Copies particle moves[count + i] onto particle moves[i] in every enabled column, for i < count
  // (moves: the destinations, then the sources; none of the sources is a destination): a removal
  // that fills its holes with a few particles from the tail moves only those.
  template <class Backend>
  void move(const std::uint32_t* moves, std::size_t count, const Backend& backend) {
    GatherList<T> reals;
    GatherList<std::uint32_t> indices;
    list_columns(reals, indices, /*stress=*/true);
    move_columns(reals, moves, count, backend);
    move_columns(indices, moves, count, backend);
  }

  // Every attribute by name with its enabled flag, and the columns of the enabled ones, for a
  // checkpoint; load() takes them back (the same attribute list and precision) and refuses others.
  void save(StateWriter& out) const {
    out.value(std::uint64_t(size_));
#define FIRN_SAVE_COLUMNS(name, n, kind, alloc, doc)                                 \
  out.text(#name);                                                                   \
  out.value(std::uint8_t(has(Attribute::name)));                                     \
  if (has(Attribute::name))                                                          \
    for (const auto& col : name##_) out.array(col);
    FIRN_PARTICLE_ATTRIBUTES(FIRN_SAVE_COLUMNS)
#undef FIRN_SAVE_COLUMNS
  }
  void load(StateReader& in) {
    const std::size_t count = std::size_t(in.value<std::uint64_t>());
#define FIRN_LOAD_COLUMNS(name, n, kind, alloc, doc)                                               \
  StateReader::expect(in.text() == #name, "checkpoint's particle attributes differ from this firn's"); \
  enabled_[int(Attribute::name)] = in.value<std::uint8_t>() != 0;                                  \
  for (auto& col : name##_) {                                                                      \
    col.clear();                                                                                   \
    if (has(Attribute::name)) in.array(col);                                                       \
    StateReader::expect(col.size() == (has(Attribute::name) ? count : 0),                          \
                        "checkpoint's particle column " #name " has the wrong length");            \
  }
    FIRN_PARTICLE_ATTRIBUTES(FIRN_LOAD_COLUMNS)
#undef FIRN_LOAD_COLUMNS
    size_ = count;
  }

 private:
  static constexpr int kGatherGroup = 4;
#define FIRN_COUNT_COLUMNS(name, n, kind, alloc, doc) +n
  static constexpr int kMaxColumns = 0 FIRN_PARTICLE_ATTRIBUTES(FIRN_COUNT_COLUMNS);
#undef FIRN_COUNT_COLUMNS
  static constexpr bool is_always(const char* alloc) { return alloc[0] == 'a'; }

  template <class S, std::size_t N>
  static void assign(S* (&dst)[N], AlignedVector<S> (&src)[N]) {
    for (std::size_t i = 0; i < N; ++i) dst[i] = src[i].empty() ? nullptr : src[i].data();
  }
  template <class S>
  static void assign(S*& dst, AlignedVector<S> (&src)[1]) {
    dst = src[0].empty() ? nullptr : src[0].data();
  }

  // The enabled columns of one scalar type, in attribute order, for gather_columns and move_columns.
  template <class S>
  struct GatherList {
    AlignedVector<S>* col[kMaxColumns] = {};
    int n = 0;
    void add(AlignedVector<S>& c) { col[n++] = &c; }
  };
  static GatherList<T>& list_of(GatherList<T>& reals, GatherList<std::uint32_t>&, AlignedVector<T>&) { return reals; }
  static GatherList<std::uint32_t>& list_of(GatherList<T>&, GatherList<std::uint32_t>& indices,
                                            AlignedVector<std::uint32_t>&) {
    return indices;
  }

  // Gathers kGatherGroup columns at a time into the spares of S's type, then swaps: the spares then
  // hold the old columns, for the next group. One pass per group reads the order once for its
  // columns (issue 15: a pass per column read it 28 times in the snowball pair's reorders). No
  // allocation (but when particles were added), so the bytes stay where the backend put them: a
  // fresh buffer each time would be zeroed by the host and, in device memory, move to the host and
  // back.
  template <class S, class Backend>
  static void gather_columns(const GatherList<S>& columns, AlignedVector<S> (&spare)[kGatherGroup],
                             const std::uint32_t* order, std::size_t count, const Backend& backend) {
    for (int first = 0; first < columns.n; first += kGatherGroup) {
      GatherColumns<S, kGatherGroup> copy{};
      copy.order = order;
      copy.count = columns.n - first < kGatherGroup ? columns.n - first : kGatherGroup;
      for (int c = 0; c < copy.count; ++c) {
        spare[c].resize(count);
        copy.out[c] = spare[c].data();
        copy.in[c] = columns.col[first + c]->data();
      }
      backend.parallel_for("particles.gather", count, copy);
      for (int c = 0; c < copy.count; ++c) columns.col[first + c]->swap(spare[c]);
    }
  }

  // The enabled columns, by scalar type and in attribute order; the stress tau only with `stress`.
  void list_columns(GatherList<T>& reals, GatherList<std::uint32_t>& indices, bool stress) {
#define FIRN_LIST_COLUMNS(name, n, kind, alloc, doc)             \
  if (stress || Attribute::name != Attribute::tau)               \
    for (auto& col : name##_)                                    \
      if (!col.empty()) list_of(reals, indices, col).add(col);
    FIRN_PARTICLE_ATTRIBUTES(FIRN_LIST_COLUMNS)
#undef FIRN_LIST_COLUMNS
  }

  template <class S, class Backend>
  static void move_columns(const GatherList<S>& columns, const std::uint32_t* moves, std::size_t count,
                           const Backend& backend) {
    for (int first = 0; first < columns.n; first += kGatherGroup) {
      MoveColumns<S, kGatherGroup> copy{};
      copy.to = moves;
      copy.from = moves + count;
      copy.count = columns.n - first < kGatherGroup ? columns.n - first : kGatherGroup;
      for (int c = 0; c < copy.count; ++c) copy.col[c] = columns.col[first + c]->data();
      backend.parallel_for("particles.move", count, copy);
    }
  }

#define FIRN_STORAGE_MEMBER(name, n, kind, alloc, doc) AlignedVector<FIRN_SCALAR_##kind(T)> name##_[n];
  FIRN_PARTICLE_ATTRIBUTES(FIRN_STORAGE_MEMBER)
#undef FIRN_STORAGE_MEMBER
  AlignedVector<T> spare_real_[kGatherGroup];
  AlignedVector<std::uint32_t> spare_index_[kGatherGroup];
  bool enabled_[int(Attribute::count)] = {};
  std::size_t size_ = 0;
};

}  // namespace firn
