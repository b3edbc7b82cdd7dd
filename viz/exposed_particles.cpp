#include "viz/exposed_particles.hpp"

#include <cmath>

#include "viz/camera.hpp"

namespace firn::viz {
namespace {

template <class T>
std::vector<std::uint32_t> exposed(const PositionColumns& p, double spacing, const std::optional<CutPlane>& cut,
                                   std::size_t max_cells) {
  const T* x[3] = {static_cast<const T*>(p.x[0]), static_cast<const T*>(p.x[1]), static_cast<const T*>(p.x[2])};
  const std::size_t n = p.count;
  auto kept = [&](std::size_t i) {
    if (!cut) return true;
    double s = 0;
    for (std::size_t d = 0; d < 3; ++d) s += (double(x[d][i]) - cut->point[d]) * cut->normal[d];
    return s <= 0;
  };
  Bounds b;
  for (std::size_t i = 0; i < n; ++i)
    if (kept(i)) b.add({double(x[0][i]), double(x[1][i]), double(x[2][i])});
  if (b.empty()) return {};
  // Cells of size `spacing` centred on lattice points, two cells of padding on every side.
  long dims[3];
  double size = 1;
  for (std::size_t d = 0; d < 3; ++d) {
    dims[d] = long(std::floor((b.hi[d] - b.lo[d]) / spacing)) + 6;
    size *= double(dims[d]);
  }
  const bool cull = spacing > 0 && size <= double(max_cells);
  auto cell = [&](std::size_t i, std::size_t d) { return long(std::floor((x[d][i] - b.lo[d]) / spacing + 0.5)) + 2; };
  auto index = [&](long i, long j, long k) { return std::size_t((k * dims[1] + j) * dims[0] + i); };
  // All 27 cells of the block around (i, j, k) are set in `grid`.
  auto surrounded = [&](const std::vector<std::uint8_t>& grid, long i, long j, long k) {
    for (long dk = -1; dk <= 1; ++dk)
      for (long dj = -1; dj <= 1; ++dj)
        for (long di = -1; di <= 1; ++di)
          if (!grid[index(i + di, j + dj, k + dk)]) return false;
    return true;
  };
  std::vector<std::uint8_t> occupied(cull ? std::size_t(size) : 0), inner(occupied.size());
  if (cull) {
    for (std::size_t i = 0; i < n; ++i)
      if (kept(i)) occupied[index(cell(i, 0), cell(i, 1), cell(i, 2))] = 1;
    // Two layers of skin stay: one alone shows the far side through the gaps between its spheres.
    for (long k = 1; k + 1 < dims[2]; ++k)
      for (long j = 1; j + 1 < dims[1]; ++j)
        for (long i = 1; i + 1 < dims[0]; ++i)
          inner[index(i, j, k)] = occupied[index(i, j, k)] && surrounded(occupied, i, j, k);
  }
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < n; ++i)
    if (kept(i) && !(cull && surrounded(inner, cell(i, 0), cell(i, 1), cell(i, 2)))) out.push_back(std::uint32_t(i));
  return out;
}

}  // namespace

std::vector<std::uint32_t> exposed_particles(const PositionColumns& positions, double spacing,
                                             const std::optional<CutPlane>& cut, std::size_t max_cells) {
  return positions.doubles ? exposed<double>(positions, spacing, cut, max_cells)
                           : exposed<float>(positions, spacing, cut, max_cells);
}

}  // namespace firn::viz
