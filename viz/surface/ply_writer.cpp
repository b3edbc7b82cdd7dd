#include "viz/surface/ply_writer.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "engine/output/atomic_file.hpp"
#include "viz/surface/hoar_crystals.hpp"

namespace firn::surface {
namespace {

static_assert(sizeof(float) == 4, "PLY float is 32-bit");

bool host_is_little_endian() {
  const std::uint32_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

}  // namespace

void write_ply(const std::string& path, const SurfaceMesh& mesh) {
  if (!host_is_little_endian()) throw std::runtime_error("write_ply: only little-endian hosts are supported");
  std::vector<Vec3f> crystal_positions, crystal_normals;
  std::vector<std::uint32_t> crystal_triangles;
  append_crystal_prisms(mesh.crystals, crystal_positions, crystal_normals, crystal_triangles);
  const std::size_t surface_vertices = mesh.vertex_count();
  const std::size_t vertices = surface_vertices + crystal_positions.size();
  const std::size_t faces = mesh.triangle_count() + crystal_triangles.size() / 3;

  AtomicFile file(path);
  std::ofstream& out = file.stream();
  out << "ply\nformat binary_little_endian 1.0\ncomment firn snow surface (Zhu-Bridson field, marching tetrahedra)\n"
      << "element vertex " << vertices << "\nproperty float x\nproperty float y\nproperty float z\n"
      << "property float nx\nproperty float ny\nproperty float nz\n"
      << "element face " << faces << "\nproperty list uchar uint vertex_indices\nend_header\n";
  std::vector<float> vertex_block;
  vertex_block.reserve(6 * vertices);
  auto add_vertices = [&](const std::vector<Vec3f>& positions, const std::vector<Vec3f>& normals) {
    for (std::size_t v = 0; v < positions.size(); ++v) {
      const Vec3f n = v < normals.size() ? normals[v] : Vec3f{{0, 0, 0}};
      vertex_block.insert(vertex_block.end(), {positions[v][0], positions[v][1], positions[v][2], n[0], n[1], n[2]});
    }
  };
  add_vertices(mesh.positions, mesh.normals);
  add_vertices(crystal_positions, crystal_normals);
  out.write(reinterpret_cast<const char*>(vertex_block.data()), std::streamsize(vertex_block.size() * sizeof(float)));

  // Each face: one count byte then three little-endian uint32 indices (13 bytes).
  std::vector<char> face_block(13 * faces);
  auto add_faces = [&, next = std::size_t(0)](const std::vector<std::uint32_t>& triangles, std::uint32_t offset) mutable {
    for (std::size_t t = 0; t < triangles.size(); t += 3, ++next) {
      char* record = &face_block[13 * next];
      record[0] = 3;
      for (int c = 0; c < 3; ++c) {
        const std::uint32_t index = triangles[t + c] + offset;
        std::memcpy(record + 1 + 4 * c, &index, 4);
      }
    }
  };
  add_faces(mesh.triangles, 0);
  add_faces(crystal_triangles, std::uint32_t(surface_vertices));
  out.write(face_block.data(), std::streamsize(face_block.size()));
  file.commit();
}

}  // namespace firn::surface
