// A flat binary image of engine state, for checkpoints (engine/scene/checkpoint.hpp): plain
// values in this machine's byte order, arrays after their length. The reader checks every length
// against what is left and throws CheckpointError rather than read past the end, so a truncated
// or foreign file is refused with a message instead of loading garbage.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace firn {

struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class StateWriter {
 public:
  template <class V>
  void value(const V& v) {
    static_assert(std::is_trivially_copyable_v<V>);
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof(V));
  }
  template <class V>
  void array(const V* data, std::size_t n) {
    static_assert(std::is_trivially_copyable_v<V>);
    value(std::uint64_t(n));
    bytes_.append(reinterpret_cast<const char*>(data), n * sizeof(V));
  }
  template <class V, class A>
  void array(const std::vector<V, A>& v) {
    array(v.data(), v.size());
  }
  void text(const std::string& s) { array(s.data(), s.size()); }
  // field() is value() here and read() in StateReader, so that one list of fields serves both.
  template <class V>
  void field(const V& v) {
    value(v);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class StateReader {
 public:
  StateReader(const char* data, std::size_t size) : at_(data), end_(data + size) {}
  explicit StateReader(const std::string& bytes) : StateReader(bytes.data(), bytes.size()) {}

  template <class V>
  void read(V& v) {
    static_assert(std::is_trivially_copyable_v<V>);
    take(&v, sizeof(V));
  }
  template <class V>
  void field(V& v) {
    read(v);
  }
  template <class V>
  V value() {
    V v;
    read(v);
    return v;
  }
  // An array's length, checked against what is left for elements of `element_size` bytes.
  std::size_t length(std::size_t element_size) {
    const std::uint64_t n = value<std::uint64_t>();
    if (element_size > 0 && n > std::uint64_t(end_ - at_) / element_size) throw CheckpointError("checkpoint is truncated");
    return std::size_t(n);
  }
  // Reads an array of exactly n elements into data.
  template <class V>
  void array(V* data, std::size_t n) {
    if (length(sizeof(V)) != n) throw CheckpointError("checkpoint array length differs from the scene's");
    take(data, n * sizeof(V));
  }
  template <class V, class A>
  void array(std::vector<V, A>& v) {
    v.resize(length(sizeof(V)));
    take(v.data(), v.size() * sizeof(V));
  }
  std::string text() {
    std::string s(length(1), '\0');
    take(s.data(), s.size());
    return s;
  }
  // Throws CheckpointError(what) unless `holds`.
  static void expect(bool holds, const std::string& what) {
    if (!holds) throw CheckpointError(what);
  }
  bool at_end() const { return at_ == end_; }

 private:
  void take(void* out, std::size_t n) {
    if (n > std::size_t(end_ - at_)) throw CheckpointError("checkpoint is truncated");
    if (n) std::memcpy(out, at_, n);
    at_ += n;
  }
  const char* at_;
  const char* end_;
};

}  // namespace firn
