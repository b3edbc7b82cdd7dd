// Particle frames as VTK XML PolyData (.vtp, "appended raw" binary, UInt64 headers), which
// ParaView and vtkXMLPolyDataReader open: one vertex per particle, in increasing particle id (while
// no particle is added or removed, index i is the same particle in every frame; the id array
// always names it). Arrays: velocity, id, material, J (total volume
// ratio), von_mises (Cauchy stress, Pa), and the material state fields allocated in this run
// (plastic_strain, Jp).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/output/atomic_file.hpp"
#include "engine/particle_fields.hpp"
#include "engine/simulation.hpp"

namespace firn {

struct VtpArray {
  std::string name;
  std::string type;  // VTK type name: Float32, Float64, Int32, UInt32
  int components;
  std::vector<unsigned char> bytes;
};

// Writes the points and arrays (values in the points' order) to `path` atomically.
void write_vtp(const std::string& path, std::size_t points, const VtpArray& positions, const std::vector<VtpArray>& arrays);

template <class S>
VtpArray vtp_array(std::string name, int components, const std::vector<S>& values) {
  const char* type = std::is_same_v<S, float>           ? "Float32"
                     : std::is_same_v<S, double>        ? "Float64"
                     : std::is_same_v<S, std::int32_t>  ? "Int32"
                                                        : "UInt32";
  VtpArray a{std::move(name), type, components, std::vector<unsigned char>(values.size() * sizeof(S))};
  std::memcpy(a.bytes.data(), values.data(), a.bytes.size());
  return a;
}

template <class T, class Backend>
void write_particles_vtp(const std::string& path, Simulation<T, Backend>& sim) {
  const ParticleView<T> pv = sim.particles();
  const std::size_t n = pv.n;
  const std::vector<std::uint32_t> by_id = sim.id_order();
  std::vector<T> x(3 * n), v(3 * n), J(n), vm(n), alpha, Jp;
  std::vector<std::int32_t> material(n);
  std::vector<std::uint32_t> id(n);
  if (pv.alpha) alpha.resize(n);
  if (pv.Jp) Jp.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t p = by_id[i];
    for (int d = 0; d < 3; ++d) x[3 * i + d] = pv.x[d][p], v[3 * i + d] = pv.v[d][p];
    id[i] = pv.id[p];
    material[i] = sim.material_of(p);
    J[i] = Simulation<T, Backend>::total_J(pv, p);
    vm[i] = particle_von_mises(pv, p);
    if (pv.alpha) alpha[i] = pv.alpha[p];
    if (pv.Jp) Jp[i] = pv.Jp[p];
  }
  std::vector<VtpArray> arrays;
  arrays.push_back(vtp_array("velocity", 3, v));
  arrays.push_back(vtp_array("id", 1, id));
  arrays.push_back(vtp_array("material", 1, material));
  arrays.push_back(vtp_array("J", 1, J));
  arrays.push_back(vtp_array("von_mises", 1, vm));
  if (pv.alpha) arrays.push_back(vtp_array("plastic_strain", 1, alpha));
  if (pv.Jp) arrays.push_back(vtp_array("Jp", 1, Jp));
  write_vtp(path, n, vtp_array("points", 3, x), arrays);
}

}  // namespace firn
