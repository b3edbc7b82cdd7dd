// Sharp-edged triangle meshes of signed distance functions by dual contouring (Ju, Losasso,
// Schaefer and Warren 2002, "Dual contouring of Hermite data", SIGGRAPH): one vertex per cell that
// the surface crosses, placed where the tangent planes at the cell's edge crossings meet (the
// minimiser of their quadratic error function), and one quad per crossed lattice edge joining the
// four cells around it. Unlike marching cubes or tetrahedra, which cut every edge and corner of a
// solid at the lattice's spacing, the tangent planes put a vertex on a tread block's edge and
// corner, so a 2 mm groove keeps its square shoulders at a few millimetres of spacing.
#pragma once

#include "viz/sdf_mesh.hpp"

namespace firn::viz {

// The zero level set of `sdf` inside [lo, hi] on a lattice of spacing `h`. Only blocks of 8^3
// cells near the surface (|distance at the block's centre| under its half diagonal plus a cell) are
// sampled, so `sdf` must not overestimate the distance. Each triangle carries its own face normal
// (flat shading keeps the edges sharp).
TriangleMesh dual_contour(const SignedDistance& sdf, const Vec3& lo, const Vec3& hi, double h);

}  // namespace firn::viz
