// The triangulation table of marching tetrahedra on the Freudenthal (Kuhn) split of a grid cell
// into six tetrahedra, all sharing the cell's main diagonal from corner (0,0,0) to (1,1,1): one
// tetrahedron per ordering (a, b, c) of the axes, with corners 0, e_a, e_a + e_b, e_a + e_b + e_c.
//
// Why tetrahedra rather than the 256-case marching cubes table (Lorensen and Cline 1987): the
// zero set of the piecewise-linear interpolant on a simplicial mesh has no ambiguous cases, and
// the split is the same in every cell (each cube face is cut by the diagonal from its smallest
// to its largest corner, seen identically by the two cells that share it), so neighbouring cells
// always agree on the surface crossing their common face. The surface is therefore a closed,
// oriented 2-manifold wherever the field is closed in the grid, with no face-ambiguity rule to
// get wrong. It samples the same grid nodes as marching cubes; the price is about twice as many
// triangles, which the smoothing then relaxes.
//
// Corner u of a cell (0..7) has offset (u & 1, u >> 1 & 1, u >> 2 & 1). Every tetrahedron edge
// joins corners u < v (v - u in {0,1}^3), so it is identified by (u, d = v - u): a node and one
// of seven positive directions. A mesh vertex lives on such a grid edge and is owned by its
// lower node. Node signs: inside when phi < 0, outside when phi >= 0 (a zero is outside, which
// keeps the surface manifold when a node lies exactly on it).
#pragma once

#include <cstdint>

namespace firn::surface {

constexpr int kEdgeDirections = 7;  // d = 1..7; direction d has offset (d & 1, d >> 1 & 1, d >> 2 & 1)

struct CellEdge {
  std::uint8_t corner;     // the lower corner u
  std::uint8_t direction;  // d in 1..7, with (u & d) == 0
};

struct CellTriangulation {
  int triangle_count;
  CellEdge triangles[12][3];  // counter-clockwise seen from outside (toward increasing phi)
};

// 256 entries: entry m triangulates a cell whose corner u is inside when bit u of m is set.
const CellTriangulation* cell_triangulations();

}  // namespace firn::surface
