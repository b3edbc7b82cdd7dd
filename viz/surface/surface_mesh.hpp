// The reconstructed snow surface: an indexed triangle mesh with one vertex per grid-edge crossing,
// per-vertex normals and material (rest) coordinates, and the hoar crystals placed on it.
// Vertex arrays are tightly packed float triples, ready for a GL vertex buffer or a PLY file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels/mat3.hpp"

namespace firn::surface {

using Vec3f = Vec3<float>;

// One hexagonal "surface hoar" crystal (thesis section 4.2): a hexagonal prism standing on the
// surface. Corner k of its base hexagon is centre + radius (cos(k pi/3) tangent +
// sin(k pi/3) cross(axis, tangent)); the prism extends `height` along `axis`.
struct HoarCrystal {
  Vec3f centre;   // on the surface (m)
  Vec3f axis;     // unit prism axis, close to the surface normal
  Vec3f tangent;  // unit, perpendicular to axis: fixes the hexagon's rotation
  float radius;   // circumradius of the hexagon (m)
  float height;   // prism height (m)
  std::uint32_t face;  // the surface triangle it sits on
};

struct SurfaceMesh {
  std::vector<Vec3f> positions;       // current-configuration vertex positions (m)
  std::vector<Vec3f> normals;         // unit outward vertex normals
  std::vector<Vec3f> rest_positions;  // material coordinates of each vertex (m): Eq. 4.11 applied to x0
  std::vector<std::uint32_t> triangles;  // three vertex indices per triangle, counter-clockwise seen from outside
  std::vector<HoarCrystal> crystals;

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return triangles.size() / 3; }
};

}  // namespace firn::surface
