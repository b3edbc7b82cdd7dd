// Particle frames as VTK XML PolyData (.vtp, "appended raw" binary, UInt64 headers), which
// ParaView and vtkXMLPolyDataReader open: one vertex per particle, in increasing particle id (while
// no particle is added or removed, index i is the same particle in every frame; the id array
// always names it). Arrays: velocity, id, material, J (total volume
// ratio), von_mises (Cauchy stress, Pa), and the material state fields allocated in this run
// (plastic_strain, Jp).
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/particle_fields.hpp"
#include "engine/simulation.hpp"
#include "kernels/backend/openmp.hpp"

namespace firn {

// VTK's name of the value type S.
template <class S>
constexpr const char* vtp_type() {
  static_assert(sizeof(S) == 4 || std::is_same_v<S, double>, "Float32, Float64, Int32 or UInt32");
  return std::is_same_v<S, float>           ? "Float32"
         : std::is_same_v<S, double>        ? "Float64"
         : std::is_same_v<S, std::int32_t>  ? "Int32"
                                            : "UInt32";
}

// An array of a .vtp file: its name, VTK type, components per point and the bytes of one value.
struct VtpLayout {
  std::string name;
  std::string type;
  int components;
  std::size_t value_bytes;
};

template <class S>
VtpLayout vtp_layout(std::string name, int components) {
  return {std::move(name), vtp_type<S>(), components, sizeof(S)};
}

// Writes `points` points to `path` atomically, streaming each array from a buffer: `fill(k, out)`
// writes array k's points x components values into `out`, k indexing `point_data` and then
// `positions` (k = point_data.size()). `buffer` is reused (and grown) for every array, so a caller
// that writes frame after frame with the same buffer allocates nothing after the first.
void write_vtp(const std::string& path, std::size_t points, const std::vector<VtpLayout>& point_data,
               const VtpLayout& positions, const std::function<void(std::size_t, unsigned char*)>& fill,
               std::vector<unsigned char>& buffer);

// Removes the particle frames (NNNNN.vtp) an earlier run left in `dir`, and `dir` itself once it
// is empty, so that a fresh run's folder holds its own frames only.
void remove_particle_frames(const std::string& dir);

// An array with its values, for the form below.
struct VtpArray {
  VtpLayout layout;
  std::vector<unsigned char> bytes;
};

template <class S>
VtpArray vtp_array(std::string name, int components, const std::vector<S>& values) {
  VtpArray a{vtp_layout<S>(std::move(name), components), std::vector<unsigned char>(values.size() * sizeof(S))};
  std::memcpy(a.bytes.data(), values.data(), a.bytes.size());
  return a;
}

// write_vtp of arrays whose values are at hand.
void write_vtp(const std::string& path, std::size_t points, const VtpArray& positions, const std::vector<VtpArray>& arrays);

// Writes a simulation's particle frames, keeping its buffers (the id order and one array's bytes)
// from frame to frame. Each array is gathered in id order by the OpenMP backend's threads when the
// run is on it (its thread count), on the calling thread otherwise.
class ParticleVtpWriter {
 public:
  template <class T, class Backend>
  void write(const std::string& path, Simulation<T, Backend>& sim) {
    using Sim = Simulation<T, Backend>;
    const ParticleView<T> pv = sim.particles();
    sim.id_order(by_id_, sort_buffers_);
    const std::uint32_t* const by_id = by_id_.data();
    int threads = 1;
    if constexpr (std::is_same_v<Backend, backend::OpenMP>) threads = sim.backend().threads();
    const backend::OpenMP host(threads);
    // out[i] = value(p) for the particle p of i-th smallest id.
    auto gather = [&](auto* out, auto value) {
      host.parallel_for("output.vtp", pv.n, [=](std::size_t i) { out[i] = value(by_id[i]); });
    };
    auto vectors = [&](unsigned char* bytes, T* const* column) {
      T* const out = reinterpret_cast<T*>(bytes);
      host.parallel_for("output.vtp", pv.n, [=](std::size_t i) {
        for (int d = 0; d < 3; ++d) out[3 * i + d] = column[d][by_id[i]];
      });
    };
    enum class Field { velocity, id, material, J, von_mises, plastic_strain, Jp };
    std::vector<VtpLayout> arrays = {vtp_layout<T>("velocity", 3), vtp_layout<std::uint32_t>("id", 1),
                                     vtp_layout<std::int32_t>("material", 1), vtp_layout<T>("J", 1),
                                     vtp_layout<T>("von_mises", 1)};
    std::vector<Field> fields = {Field::velocity, Field::id, Field::material, Field::J, Field::von_mises};
    if (pv.alpha) arrays.push_back(vtp_layout<T>("plastic_strain", 1)), fields.push_back(Field::plastic_strain);
    if (pv.Jp) arrays.push_back(vtp_layout<T>("Jp", 1)), fields.push_back(Field::Jp);
    auto fill = [&](std::size_t k, unsigned char* bytes) {
      T* const values = reinterpret_cast<T*>(bytes);
      if (k == fields.size()) return vectors(bytes, pv.x);
      switch (fields[k]) {
        case Field::velocity: return vectors(bytes, pv.v);
        case Field::id: return gather(reinterpret_cast<std::uint32_t*>(bytes), [=](std::size_t p) { return pv.id[p]; });
        case Field::material:
          return gather(reinterpret_cast<std::int32_t*>(bytes), [&sim](std::size_t p) { return sim.material_of(p); });
        case Field::J: return gather(values, [=](std::size_t p) { return Sim::total_J(pv, p); });
        case Field::von_mises: return gather(values, [=](std::size_t p) { return particle_von_mises(pv, p); });
        case Field::plastic_strain: return gather(values, [=](std::size_t p) { return pv.alpha[p]; });
        case Field::Jp: return gather(values, [=](std::size_t p) { return pv.Jp[p]; });
      }
    };
    write_vtp(path, pv.n, arrays, vtp_layout<T>("points", 3), fill, buffer_);
  }

 private:
  std::vector<std::uint32_t> by_id_;
  RadixBuffers sort_buffers_;
  std::vector<unsigned char> buffer_;
};

// One frame, buffers and all (tests; a run keeps a ParticleVtpWriter).
template <class T, class Backend>
void write_particles_vtp(const std::string& path, Simulation<T, Backend>& sim) {
  ParticleVtpWriter().write(path, sim);
}

}  // namespace firn
