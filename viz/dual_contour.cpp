#include "viz/dual_contour.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace firn::viz {
namespace {

constexpr int kBlock = 8;  // cells per block side, for the narrow band

// The lattice of samples: n[d] + 1 points along axis d.
struct Lattice {
  Vec3 lo;
  double h;
  int n[3];
  std::vector<float> d;  // (n0 + 1)(n1 + 1)(n2 + 1) distances
  std::size_t index(int i, int j, int k) const {
    return (std::size_t(k) * std::size_t(n[1] + 1) + std::size_t(j)) * std::size_t(n[0] + 1) + std::size_t(i);
  }
  Vec3 point(int i, int j, int k) const { return {lo[0] + i * h, lo[1] + j * h, lo[2] + k * h}; }
  float at(int i, int j, int k) const { return d[index(i, j, k)]; }
};

// Samples every point of the blocks near the surface; a far block's points all take the sign of
// its centre's distance, which no point of the block can differ from.
Lattice sample(const SignedDistance& sdf, const Vec3& lo, const Vec3& hi, double h) {
  Lattice l;
  l.lo = lo, l.h = h;
  for (std::size_t a = 0; a < 3; ++a) l.n[a] = std::max(1, int(std::ceil((hi[a] - lo[a]) / h)));
  l.d.assign(std::size_t(l.n[0] + 1) * std::size_t(l.n[1] + 1) * std::size_t(l.n[2] + 1), 0.0f);
  const double half_diagonal = 0.5 * std::sqrt(3.0) * kBlock * h;
  Vec3 normal;
  for (int bk = 0; bk <= l.n[2]; bk += kBlock)
    for (int bj = 0; bj <= l.n[1]; bj += kBlock)
      for (int bi = 0; bi <= l.n[0]; bi += kBlock) {
        const int ei = std::min(bi + kBlock, l.n[0]), ej = std::min(bj + kBlock, l.n[1]), ek = std::min(bk + kBlock, l.n[2]);
        const double centre = sdf(l.point(bi + kBlock / 2, bj + kBlock / 2, bk + kBlock / 2), normal);
        const bool near = std::abs(centre) <= half_diagonal + h;
        for (int k = bk; k <= ek; ++k)
          for (int j = bj; j <= ej; ++j)
            for (int i = bi; i <= ei; ++i) l.d[l.index(i, j, k)] = near ? float(sdf(l.point(i, j, k), normal)) : float(centre);
      }
  return l;
}

// The point minimising sum (n_i . (x - p_i))^2 + w |x - m|^2 (m: the crossings' mean; the small w
// keeps flat and straight-edged cells, whose planes do not fix every direction, at the mean), by
// Cramer's rule on the 3 x 3 normal equations; then kept inside the cell.
Vec3 cell_vertex(const std::vector<Vec3>& p, const std::vector<Vec3>& n, const Vec3& cell_lo, double h) {
  Vec3 m = {0, 0, 0};
  for (const Vec3& q : p) m = m + (1.0 / double(p.size())) * q;
  const double w = 0.05;
  double a[3][3] = {{w, 0, 0}, {0, w, 0}, {0, 0, w}}, b[3] = {0, 0, 0};
  for (std::size_t s = 0; s < p.size(); ++s) {
    const double c = dot(n[s], p[s] - m);  // about m: the solution is m + x
    for (std::size_t r = 0; r < 3; ++r) {
      for (std::size_t q = 0; q < 3; ++q) a[r][q] += n[s][r] * n[s][q];
      b[r] += n[s][r] * c;
    }
  }
  auto det = [](const double (&x)[3][3]) {
    return x[0][0] * (x[1][1] * x[2][2] - x[1][2] * x[2][1]) - x[0][1] * (x[1][0] * x[2][2] - x[1][2] * x[2][0]) +
           x[0][2] * (x[1][0] * x[2][1] - x[1][1] * x[2][0]);
  };
  const double d = det(a);
  Vec3 x = m;
  for (int c = 0; c < 3; ++c) {
    double ac[3][3];
    for (int r = 0; r < 3; ++r)
      for (int q = 0; q < 3; ++q) ac[r][q] = q == c ? b[r] : a[r][q];
    x[std::size_t(c)] += det(ac) / d;
  }
  for (std::size_t c = 0; c < 3; ++c) x[c] = std::clamp(x[c], cell_lo[c], cell_lo[c] + h);
  return x;
}

}  // namespace

TriangleMesh dual_contour(const SignedDistance& sdf, const Vec3& lo, const Vec3& hi, double h) {
  const Lattice l = sample(sdf, lo, hi, h);
  // The crossing of the lattice edge from (i, j, k) along `axis` and the normal there: the zero of
  // the distance along the edge by regula falsi (Illinois), not the linear interpolation of the two
  // samples, which outside an edge or corner of the solid (where the distance is rounded) lands off
  // the surface, where the normal is tilted; found once per edge.
  struct Hermite {
    Vec3 p, n;
  };
  std::unordered_map<std::size_t, Hermite> crossings;
  auto crossing = [&](int i, int j, int k, int axis) -> const Hermite& {
    const std::size_t key = 3 * l.index(i, j, k) + std::size_t(axis);
    auto found = crossings.find(key);
    if (found != crossings.end()) return found->second;
    int o[3] = {i, j, k};
    ++o[axis];
    const Vec3 a = l.point(i, j, k), b = l.point(o[0], o[1], o[2]);
    double t0 = 0, t1 = 1, d0 = l.at(i, j, k), d1 = l.at(o[0], o[1], o[2]);
    Hermite x;
    double t = d0 / (d0 - d1);
    for (int iteration = 0; iteration < 12; ++iteration) {
      const double d = sdf(a + t * (b - a), x.n);
      if (std::abs(d) < 1e-4 * l.h) break;
      if ((d < 0) == (d0 < 0)) {
        t0 = t, d0 = d, d1 *= iteration > 0 ? 0.5 : 1;
      } else {
        t1 = t, d1 = d, d0 *= iteration > 0 ? 0.5 : 1;
      }
      t = t0 + (t1 - t0) * d0 / (d0 - d1);
    }
    x.p = a + t * (b - a);
    sdf(x.p, x.n);
    return crossings.emplace(key, x).first->second;
  };
  auto crosses = [&](int i, int j, int k, int axis) {
    int o[3] = {i, j, k};
    ++o[axis];
    return (l.at(i, j, k) < 0) != (l.at(o[0], o[1], o[2]) < 0);
  };
  // One vertex per crossed cell, found from the cell's twelve edges.
  std::unordered_map<std::size_t, Vec3> vertex;
  auto cell_vertex_at = [&](int i, int j, int k) -> const Vec3& {
    const std::size_t key = l.index(i, j, k);
    auto found = vertex.find(key);
    if (found != vertex.end()) return found->second;
    std::vector<Vec3> p, n;
    for (int axis = 0; axis < 3; ++axis)
      for (int e = 0; e < 4; ++e) {
        int c[3] = {i, j, k};
        c[(axis + 1) % 3] += e & 1, c[(axis + 2) % 3] += e >> 1;
        if (!crosses(c[0], c[1], c[2], axis)) continue;
        const Hermite& x = crossing(c[0], c[1], c[2], axis);
        p.push_back(x.p);
        n.push_back(x.n);
      }
    return vertex.emplace(key, cell_vertex(p, n, l.point(i, j, k), l.h)).first->second;
  };
  TriangleMesh mesh;
  auto emit = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 normal = cross(b - a, c - a);
    const double len = length(normal);
    if (len == 0) return;
    for (const Vec3* v : {&a, &b, &c}) {
      for (double x : *v) mesh.vertices.push_back(float(x));
      for (double x : normal) mesh.vertices.push_back(float(x / len));
    }
  };
  // A quad per crossed edge between interior lattice points: the four cells sharing it, ordered
  // around the edge so the face points from the inside (negative) end to the outside.
  for (int k = 0; k <= l.n[2]; ++k)
    for (int j = 0; j <= l.n[1]; ++j)
      for (int i = 0; i <= l.n[0]; ++i)
        for (int axis = 0; axis < 3; ++axis) {
          const int u = (axis + 1) % 3, v = (axis + 2) % 3;
          int c[3] = {i, j, k};
          if (c[axis] >= l.n[axis] || !crosses(i, j, k, axis)) continue;
          int q[4][3];
          const int du[4] = {-1, 0, 0, -1}, dv[4] = {-1, -1, 0, 0};
          bool inside_cells = true;
          for (int s = 0; s < 4; ++s) {
            q[s][0] = i, q[s][1] = j, q[s][2] = k;
            q[s][u] += du[s], q[s][v] += dv[s];
            inside_cells = inside_cells && q[s][u] >= 0 && q[s][v] >= 0 && q[s][u] < l.n[u] && q[s][v] < l.n[v];
          }
          if (!inside_cells) continue;
          const Vec3 a = cell_vertex_at(q[0][0], q[0][1], q[0][2]), b = cell_vertex_at(q[1][0], q[1][1], q[1][2]),
                     cc = cell_vertex_at(q[2][0], q[2][1], q[2][2]), d = cell_vertex_at(q[3][0], q[3][1], q[3][2]);
          // (u, v, axis) is right-handed; going -u-v, +u-v, +u+v, -u+v turns about +axis, so the
          // face points along +axis: right when the edge goes from inside to outside.
          if (l.at(i, j, k) < 0) {
            emit(a, b, cc);
            emit(a, cc, d);
          } else {
            emit(a, cc, b);
            emit(a, d, cc);
          }
        }
  return mesh;
}

}  // namespace firn::viz
