// Checks that a triangle mesh is a closed, consistently oriented 2-manifold, and measures the volume
// it encloses. Used by the tests on every mesh and PLY file they produce.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "viz/surface/surface_mesh.hpp"

namespace firn::surface {

struct MeshTopology {
  std::size_t vertices = 0, edges = 0, faces = 0;
  std::size_t boundary_edges = 0;         // used by one triangle
  std::size_t non_manifold_edges = 0;     // used by more than two triangles
  std::size_t misoriented_edges = 0;      // used twice in the same direction
  std::size_t degenerate_triangles = 0;   // a repeated vertex index
  std::size_t non_manifold_vertices = 0;  // whose triangles do not form one closed fan
  std::size_t isolated_vertices = 0;      // in no triangle

  long euler_characteristic() const { return long(vertices) - long(edges) + long(faces); }
  bool closed_manifold() const {
    return boundary_edges == 0 && non_manifold_edges == 0 && misoriented_edges == 0 && degenerate_triangles == 0 &&
           non_manifold_vertices == 0 && isolated_vertices == 0;
  }
};

MeshTopology analyse_topology(const std::vector<std::uint32_t>& triangles, std::size_t vertex_count);

// Volume enclosed by a closed outward-oriented mesh (divergence theorem: sum of a . (b x c) / 6).
double enclosed_volume(const std::vector<Vec3f>& positions, const std::vector<std::uint32_t>& triangles);

}  // namespace firn::surface
