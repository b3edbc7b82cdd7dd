#include "viz/surface/hoar_crystals.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "viz/surface/material_noise.hpp"

namespace firn::surface {
namespace {

constexpr float kPi = 3.14159265358979f;

Vec3f normalised(const Vec3f& v) {
  const float length = norm(v);
  return length > 0 ? (1 / length) * v : v;
}

// The affine map of one triangle from rest to current coordinates, restricted to its plane: a rest
// vector is projected onto the rest triangle's edges (least squares) and rebuilt from the current
// edges.
struct TriangleMap {
  Vec3f rest_origin, rest_edge[2], current_origin, current_edge[2];
  float gram[3];  // e0.e0, e0.e1, e1.e1 of the rest edges
  float det;

  TriangleMap(const SurfaceMesh& mesh, std::size_t t) {
    const std::uint32_t* v = &mesh.triangles[3 * t];
    rest_origin = mesh.rest_positions[v[0]];
    current_origin = mesh.positions[v[0]];
    for (int k = 0; k < 2; ++k) {
      rest_edge[k] = mesh.rest_positions[v[k + 1]] - rest_origin;
      current_edge[k] = mesh.positions[v[k + 1]] - current_origin;
    }
    gram[0] = dot(rest_edge[0], rest_edge[0]);
    gram[1] = dot(rest_edge[0], rest_edge[1]);
    gram[2] = dot(rest_edge[1], rest_edge[1]);
    det = gram[0] * gram[2] - gram[1] * gram[1];
  }
  bool degenerate() const { return !(det > 1e-12f * gram[0] * gram[2]); }
  // Barycentric-edge coordinates (a, b) of the rest vector's projection: a e0 + b e1.
  void coordinates(const Vec3f& rest_vector, float& a, float& b) const {
    const float r0 = dot(rest_vector, rest_edge[0]), r1 = dot(rest_vector, rest_edge[1]);
    a = (gram[2] * r0 - gram[1] * r1) / det;
    b = (gram[0] * r1 - gram[1] * r0) / det;
  }
  Vec3f map_vector(const Vec3f& rest_vector) const {
    float a, b;
    coordinates(rest_vector, a, b);
    return a * current_edge[0] + b * current_edge[1];
  }
  // The current position of the rest point's projection, clamped into the triangle.
  Vec3f map_point_into_triangle(const Vec3f& rest_point) const {
    float a, b;
    coordinates(rest_point - rest_origin, a, b);
    a = std::fmax(a, 0.0f);
    b = std::fmax(b, 0.0f);
    if (a + b > 1) {
      const float s = 1 / (a + b);
      a *= s;
      b *= s;
    }
    return current_origin + a * current_edge[0] + b * current_edge[1];
  }
};

struct SiteKeyHash {
  std::size_t operator()(std::uint64_t key) const { return std::size_t(mix_bits(std::uint32_t(key ^ (key >> 32)))); }
};

std::uint64_t site_key(const std::int32_t q[3]) {
  const std::uint64_t mask = (1u << 21) - 1;
  return (std::uint64_t(q[0]) & mask) << 42 | (std::uint64_t(q[1]) & mask) << 21 | (std::uint64_t(q[2]) & mask);
}

}  // namespace

std::vector<HoarCrystal> place_hoar_crystals(const SurfaceMesh& mesh, const SurfaceParams& params, double h) {
  std::vector<HoarCrystal> crystals;
  if (!params.crystals || params.crystal_probability <= 0) return crystals;
  const float spacing = float(params.crystal_spacing * h);
  const std::uint32_t seed = mix_bits(params.seed ^ 0x4c7a1u);  // independent of the vertex noise
  struct Winner {
    float distance2;
    std::uint32_t triangle;
    std::int32_t cell[3];
  };
  std::unordered_map<std::uint64_t, Winner, SiteKeyHash> winners;
  auto site_of = [&](const std::int32_t q[3]) {
    Vec3f site;
    for (int d = 0; d < 3; ++d) site[d] = (float(q[d]) + 0.15f + 0.7f * unit_interval(lattice_hash(q[0], q[1], q[2], seed + 1u + d))) * spacing;
    return site;
  };
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const std::uint32_t* v = &mesh.triangles[3 * t];
    const Vec3f centroid = (1.0f / 3) * (mesh.rest_positions[v[0]] + mesh.rest_positions[v[1]] + mesh.rest_positions[v[2]]);
    std::int32_t q[3];
    for (int d = 0; d < 3; ++d) q[d] = std::int32_t(std::floor(centroid[d] / spacing));
    if (unit_interval(lattice_hash(q[0], q[1], q[2], seed)) >= params.crystal_probability) continue;
    const Vec3f offset = centroid - site_of(q);
    const Winner candidate{dot(offset, offset), std::uint32_t(t), {q[0], q[1], q[2]}};
    auto [it, inserted] = winners.emplace(site_key(q), candidate);
    if (!inserted && candidate.distance2 < it->second.distance2) it->second = candidate;
  }
  std::vector<Winner> chosen;
  chosen.reserve(winners.size());
  for (const auto& entry : winners) chosen.push_back(entry.second);
  std::sort(chosen.begin(), chosen.end(), [](const Winner& a, const Winner& b) { return a.triangle < b.triangle; });

  for (const Winner& w : chosen) {
    const TriangleMap map(mesh, w.triangle);
    const Vec3f normal = normalised(cross(map.current_edge[0], map.current_edge[1]));
    if (map.degenerate() || norm(normal) == 0) continue;
    auto hashed = [&](std::uint32_t k) { return unit_interval(lattice_hash(w.cell[0], w.cell[1], w.cell[2], seed + 16u + k)); };
    // A hashed material direction (uniform on the sphere), carried into the current configuration
    // by the triangle's map; should it fall along the normal, the first edge stands in.
    const float azimuth = 2 * kPi * hashed(0), cos_polar = 2 * hashed(5) - 1;
    const float sin_polar = std::sqrt(std::fmax(0.0f, 1 - cos_polar * cos_polar));
    const Vec3f material_direction = {{sin_polar * std::cos(azimuth), sin_polar * std::sin(azimuth), cos_polar}};
    Vec3f tangent = map.map_vector(material_direction);
    tangent = normalised(tangent - dot(tangent, normal) * normal);
    if (norm(tangent) == 0) tangent = normalised(map.current_edge[0]);
    const Vec3f bitangent = cross(normal, tangent);
    const float tilt = float(params.crystal_tilt) * hashed(1), tilt_direction = 2 * kPi * hashed(2);
    const Vec3f axis = normalised(std::cos(tilt) * normal + std::sin(tilt) * (std::cos(tilt_direction) * tangent +
                                                                              std::sin(tilt_direction) * bitangent));
    HoarCrystal c;
    c.centre = map.map_point_into_triangle(site_of(w.cell));
    c.axis = axis;
    c.tangent = normalised(tangent - dot(tangent, axis) * axis);
    c.radius = float(params.crystal_radius * h) * (0.5f + 0.5f * hashed(3));
    c.height = float(params.crystal_height * h) * (0.5f + 0.5f * hashed(4));
    c.face = w.triangle;
    crystals.push_back(c);
  }
  return crystals;
}

void append_crystal_prisms(const std::vector<HoarCrystal>& crystals, std::vector<Vec3f>& positions,
                           std::vector<Vec3f>& normals, std::vector<std::uint32_t>& triangles) {
  for (const HoarCrystal& c : crystals) {
    const std::uint32_t base = std::uint32_t(positions.size());
    const Vec3f bitangent = cross(c.axis, c.tangent);
    for (int level = 0; level < 2; ++level)
      for (int k = 0; k < 6; ++k) {
        const float angle = float(k) * kPi / 3;
        const Vec3f radial = std::cos(angle) * c.tangent + std::sin(angle) * bitangent;
        positions.push_back(c.centre + c.radius * radial + (level ? c.height : 0.0f) * c.axis);
        normals.push_back(normalised(radial + (level ? 1.0f : -1.0f) * c.axis));
      }
    // Vertices base + k (bottom) and base + 6 + k (top), k counter-clockwise about the axis.
    for (int k = 1; k + 1 < 6; ++k) {
      triangles.insert(triangles.end(), {base, base + k + 1, base + k});              // bottom, facing -axis
      triangles.insert(triangles.end(), {base + 6, base + 6 + k, base + 6 + k + 1});  // top, facing +axis
    }
    for (std::uint32_t k = 0; k < 6; ++k) {
      const std::uint32_t k1 = (k + 1) % 6;
      triangles.insert(triangles.end(), {base + k, base + k1, base + 6 + k1});
      triangles.insert(triangles.end(), {base + k, base + 6 + k1, base + 6 + k});
    }
  }
}

}  // namespace firn::surface
