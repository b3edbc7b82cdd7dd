// Triangle meshes of signed distance functions, so that any collider shape the engine can
// describe by a distance (plane, box, cylinder, a tire with tread) is drawn the same way.
#pragma once

#include <functional>
#include <vector>

#include "viz/mat4.hpp"

namespace firn::viz {

// Signed distance at x (negative inside) and the outward unit normal there.
using SignedDistance = std::function<double(const Vec3& x, Vec3& normal)>;

// Triangles as (position, normal) vertex pairs: 6 floats per vertex, 3 vertices per triangle.
struct TriangleMesh {
  std::vector<float> vertices;
  std::size_t vertex_count() const { return vertices.size() / 6; }
};

// The solid of `sdf` cut to the box [lo, hi] (the intersection: max of the two distances), so
// that a half-space shows as a closed block of the domain rather than an open sheet.
SignedDistance clip_to_box(SignedDistance sdf, const Vec3& lo, const Vec3& hi);

// The zero level set of `sdf` inside the box [lo, hi], sampled on a grid of `cells` cells along
// the box's longest side, by marching tetrahedra (each cube split into six tetrahedra around its
// main diagonal; Doi and Koide 1991). Normals come from the distance function.
TriangleMesh mesh_signed_distance(const SignedDistance& sdf, const Vec3& lo, const Vec3& hi, int cells);

}  // namespace firn::viz
