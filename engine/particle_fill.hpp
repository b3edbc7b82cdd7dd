// Regular particle lattices: `per_cell` particles per axis in every grid cell, at offsets
// (i + 1/2) / per_cell of the cell, e.g. 0.25 and 0.75 for two per axis (DESIGN.md section 6).
// Cells are those of the grid anchored at `origin` with spacing dx.
#pragma once

#include <array>
#include <cmath>
#include <vector>

namespace firn {

using Point = std::array<double, 3>;

// Lattice points inside [lo, hi) for which inside(point) is true.
template <class Inside>
std::vector<Point> fill_lattice(const Point& origin, double dx, int per_cell, const Point& lo, const Point& hi,
                                Inside inside) {
  const double h = dx / per_cell;
  int first[3], count[3];
  for (int d = 0; d < 3; ++d) {
    // Points sit at origin + (j + 1/2) h; take those with lo <= point < hi.
    first[d] = int(std::ceil((lo[d] - origin[d]) / h - 0.5 - 1e-9));
    count[d] = int(std::ceil((hi[d] - origin[d]) / h - 0.5 - 1e-9)) - first[d];
  }
  std::vector<Point> points;
  for (int i = 0; i < count[0]; ++i)
    for (int j = 0; j < count[1]; ++j)
      for (int k = 0; k < count[2]; ++k) {
        const Point p = {origin[0] + (first[0] + i + 0.5) * h, origin[1] + (first[1] + j + 0.5) * h,
                         origin[2] + (first[2] + k + 0.5) * h};
        if (inside(p)) points.push_back(p);
      }
  return points;
}

inline std::vector<Point> fill_box(const Point& origin, double dx, int per_cell, const Point& lo, const Point& hi) {
  return fill_lattice(origin, dx, per_cell, lo, hi, [](const Point&) { return true; });
}

inline std::vector<Point> fill_sphere(const Point& origin, double dx, int per_cell, const Point& centre, double radius) {
  const Point lo = {centre[0] - radius, centre[1] - radius, centre[2] - radius};
  const Point hi = {centre[0] + radius, centre[1] + radius, centre[2] + radius};
  return fill_lattice(origin, dx, per_cell, lo, hi, [&](const Point& p) {
    const double a = p[0] - centre[0], b = p[1] - centre[1], c = p[2] - centre[2];
    return a * a + b * b + c * c < radius * radius;
  });
}

}  // namespace firn
