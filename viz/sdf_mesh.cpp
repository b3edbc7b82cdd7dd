#include "viz/sdf_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace firn::viz {
namespace {

// Corner c of a cube has offset (c & 1, c >> 1 & 1, c >> 2 & 1); six tetrahedra share the diagonal 0-7.
constexpr int kTetrahedra[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

struct Sample {
  Vec3 x;
  double d;
};

class Mesher {
 public:
  Mesher(const SignedDistance& sdf, TriangleMesh& out) : sdf_(sdf), out_(out) {}

  void tetrahedron(const Sample* s[4]) {
    int inside[4], outside[4], ni = 0, no = 0;
    for (int i = 0; i < 4; ++i) (s[i]->d < 0 ? inside[ni++] : outside[no++]) = i;
    if (ni == 0 || no == 0) return;
    if (ni == 1 || no == 1) {  // one corner apart: one triangle across its three edges
      const int apart = ni == 1 ? inside[0] : outside[0];
      const int* others = ni == 1 ? outside : inside;
      triangle(edge(*s[apart], *s[others[0]]), edge(*s[apart], *s[others[1]]), edge(*s[apart], *s[others[2]]));
      return;
    }
    // two and two: a quad through the four crossing edges
    const Vec3 a = edge(*s[inside[0]], *s[outside[0]]), b = edge(*s[inside[0]], *s[outside[1]]),
               c = edge(*s[inside[1]], *s[outside[1]]), d = edge(*s[inside[1]], *s[outside[0]]);
    triangle(a, b, c);
    triangle(a, c, d);
  }

 private:
  static Vec3 edge(const Sample& p, const Sample& q) {
    const double t = p.d / (p.d - q.d);
    return p.x + t * (q.x - p.x);
  }
  void vertex(const Vec3& x) {
    Vec3 n;
    sdf_(x, n);
    for (double v : x) out_.vertices.push_back(float(v));
    for (double v : n) out_.vertices.push_back(float(v));
  }
  void triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    if (length(cross(b - a, c - a)) == 0) return;
    vertex(a);
    vertex(b);
    vertex(c);
  }

  const SignedDistance& sdf_;
  TriangleMesh& out_;
};

}  // namespace

SignedDistance clip_to_box(SignedDistance sdf, const Vec3& lo, const Vec3& hi) {
  return [sdf = std::move(sdf), lo, hi](const Vec3& x, Vec3& normal) {
    // Exact box distance (Quilez, "distance functions"): outside, the length of the excess;
    // inside, the (negative) distance to the nearest face.
    Vec3 q, outside = {0, 0, 0};
    std::size_t nearest = 0;
    for (std::size_t d = 0; d < 3; ++d) {
      const double c = 0.5 * (lo[d] + hi[d]), r = x[d] - c;
      q[d] = std::abs(r) - 0.5 * (hi[d] - lo[d]);
      outside[d] = q[d] > 0 ? (r > 0 ? q[d] : -q[d]) : 0;
      if (q[d] > q[nearest]) nearest = d;
    }
    const double out = length(outside);
    double box;
    Vec3 box_normal = {0, 0, 0};
    if (out > 0) {
      box = out;
      box_normal = (1 / out) * outside;
    } else {
      box = q[nearest];
      box_normal[nearest] = x[nearest] > 0.5 * (lo[nearest] + hi[nearest]) ? 1 : -1;
    }
    const double d = sdf(x, normal);
    if (box > d) {
      normal = box_normal;
      return box;
    }
    return d;
  };
}

TriangleMesh mesh_signed_distance(const SignedDistance& sdf, const Vec3& lo, const Vec3& hi, int cells) {
  const double h = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) / cells;
  int n[3];
  for (int d = 0; d < 3; ++d) n[d] = std::max(1, int(std::ceil((hi[std::size_t(d)] - lo[std::size_t(d)]) / h)));
  // Samples on the (n + 1)^3 lattice, one z-slab pair at a time.
  auto sample = [&](int i, int j, int k) {
    Sample s;
    s.x = {lo[0] + i * h, lo[1] + j * h, lo[2] + k * h};
    Vec3 normal;
    s.d = sdf(s.x, normal);
    return s;
  };
  const std::size_t slab = std::size_t(n[0] + 1) * std::size_t(n[1] + 1);
  std::vector<Sample> below(slab), above(slab);
  auto fill = [&](std::vector<Sample>& s, int k) {
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i) s[std::size_t(j) * std::size_t(n[0] + 1) + std::size_t(i)] = sample(i, j, k);
  };
  TriangleMesh mesh;
  Mesher mesher(sdf, mesh);
  fill(below, 0);
  for (int k = 0; k < n[2]; ++k) {
    fill(above, k + 1);
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const Sample* corner[8];
        for (int c = 0; c < 8; ++c) {
          const std::vector<Sample>& layer = (c >> 2 & 1) ? above : below;
          corner[c] = &layer[std::size_t(j + (c >> 1 & 1)) * std::size_t(n[0] + 1) + std::size_t(i + (c & 1))];
        }
        bool any_in = false, any_out = false;
        for (const Sample* s : corner) (s->d < 0 ? any_in : any_out) = true;
        if (!any_in || !any_out) continue;
        for (const auto& tet : kTetrahedra) {
          const Sample* s[4] = {corner[tet[0]], corner[tet[1]], corner[tet[2]], corner[tet[3]]};
          mesher.tetrahedron(s);
        }
      }
    std::swap(below, above);
  }
  return mesh;
}

}  // namespace firn::viz
