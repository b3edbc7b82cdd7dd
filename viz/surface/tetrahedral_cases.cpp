// Derives the cell triangulation table once, from the six Freudenthal tetrahedra: for each sign
// case of a tetrahedron, the zero set of a linear function is a triangle (one corner separated
// from three) or a quadrilateral (two from two), cut into two triangles along a fixed diagonal.
// Winding is decided on the unit cell with every crossing at its edge midpoint, where no triangle
// is degenerate: the triangle's normal must point from the inside corners' centroid toward the
// outside corners'. Moving the crossings along their edges never flips a triangle (it stays on the
// same side of the separated corner, and the quadrilateral stays planar and convex), so the
// winding holds for any field values.
#include "viz/surface/tetrahedral_cases.hpp"

#include <array>
#include <utility>

namespace firn::surface {
namespace {

struct Point {
  double x, y, z;
};

Point corner_point(int u) { return {double(u & 1), double(u >> 1 & 1), double(u >> 2 & 1)}; }

Point edge_midpoint(int u, int v) {
  const Point a = corner_point(u), b = corner_point(v);
  return {(a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2};
}

// Corners u < v of a tetrahedron edge as (lower corner, direction).
CellEdge cell_edge(int u, int v) {
  if ((u & v) != u) std::swap(u, v);
  return {std::uint8_t(u), std::uint8_t(v ^ u)};
}

struct TableBuilder {
  std::array<CellTriangulation, 256> table{};

  TableBuilder() {
    const int axes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int inside = 0; inside < 256; ++inside) {
      CellTriangulation& cell = table[inside];
      cell.triangle_count = 0;
      for (const auto& order : axes) {
        const int c1 = 1 << order[0], c2 = c1 | 1 << order[1];
        const int corners[4] = {0, c1, c2, 7};
        int in[4], out[4], n_in = 0, n_out = 0;
        for (int c : corners) {
          if (inside >> c & 1) in[n_in++] = c;
          else out[n_out++] = c;
        }
        if (n_in == 1) {
          add(cell, in, n_in, out, n_out, {in[0], out[0]}, {in[0], out[1]}, {in[0], out[2]});
        } else if (n_out == 1) {
          add(cell, in, n_in, out, n_out, {in[0], out[0]}, {in[1], out[0]}, {in[2], out[0]});
        } else if (n_in == 2) {
          // Quadrilateral on edges (i0,o0), (i0,o1), (i1,o1), (i1,o0), in cyclic order.
          add(cell, in, n_in, out, n_out, {in[0], out[0]}, {in[0], out[1]}, {in[1], out[1]});
          add(cell, in, n_in, out, n_out, {in[0], out[0]}, {in[1], out[1]}, {in[1], out[0]});
        }
      }
    }
  }

  static void add(CellTriangulation& cell, const int* in, int n_in, const int* out, int n_out,
                  std::pair<int, int> e0, std::pair<int, int> e1, std::pair<int, int> e2) {
    const Point a = edge_midpoint(e0.first, e0.second), b = edge_midpoint(e1.first, e1.second),
                c = edge_midpoint(e2.first, e2.second);
    const Point ab = {b.x - a.x, b.y - a.y, b.z - a.z}, ac = {c.x - a.x, c.y - a.y, c.z - a.z};
    const Point normal = {ab.y * ac.z - ab.z * ac.y, ab.z * ac.x - ab.x * ac.z, ab.x * ac.y - ab.y * ac.x};
    Point toward_outside = {0, 0, 0};
    for (int i = 0; i < n_out; ++i) {
      const Point p = corner_point(out[i]);
      toward_outside = {toward_outside.x + p.x / n_out, toward_outside.y + p.y / n_out, toward_outside.z + p.z / n_out};
    }
    for (int i = 0; i < n_in; ++i) {
      const Point p = corner_point(in[i]);
      toward_outside = {toward_outside.x - p.x / n_in, toward_outside.y - p.y / n_in, toward_outside.z - p.z / n_in};
    }
    const bool outward = normal.x * toward_outside.x + normal.y * toward_outside.y + normal.z * toward_outside.z > 0;
    CellEdge* tri = cell.triangles[cell.triangle_count++];
    tri[0] = cell_edge(e0.first, e0.second);
    tri[1] = outward ? cell_edge(e1.first, e1.second) : cell_edge(e2.first, e2.second);
    tri[2] = outward ? cell_edge(e2.first, e2.second) : cell_edge(e1.first, e1.second);
  }
};

}  // namespace

const CellTriangulation* cell_triangulations() {
  static const TableBuilder builder;
  return builder.table.data();
}

}  // namespace firn::surface
