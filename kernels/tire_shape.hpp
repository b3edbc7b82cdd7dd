// A tire with a tread pattern as a signed distance function, in the tire's own frame: the axle is
// the z axis through the origin, the tire rolls in the x-y plane (issue 5; the thesis' section
// 4.3.2 and Figure 4.8 describe the three patterns, engine/tread_patterns.cpp draws them).
//
// The solid is the union of (a tire without blocks is the plain cylinder r <= R, |z| <= W/2, its
// shoulders rounded to `shoulder`: the cylinder r <= R - s, |z| <= W/2 - s grown by a ball of radius
// s, whose distance is that cylinder's less s, exactly)
//   the carcass: the cylinder r <= R - depth, |z| <= W/2 (r = sqrt(x^2 + y^2));
//   the tread:   the points of the band R - depth <= r <= R, |z| <= W/2 whose unrolled coordinates
//                (arc length s = r phi along the circumference, lateral z) fall inside one of the
//                pattern's blocks. A block is a convex or simple polygon drawn on one pitch of the
//                unrolled tread, vertices (u, w) with u in pitch lengths (0..1 is one pitch, a block
//                may reach into the next) and w in tire widths (-1/2..1/2); it repeats `pitches`
//                times around the tire.
//
// Distance: the carcass is exact (capped cylinder). A block is the radial extrusion of its
// polygon's 2D signed distance d2(s, z), measured in the unrolled plane at radius rho (the query's
// own radius r in the band, sqrt(r R) above it), over r <= R (h = r - R), combined as for any
// extrusion: d = min(max(d2, h), 0) + |max((d2, h), 0)|; the union takes the minimum. Outside the
// tire the result is the distance to the nearest surface up to the bending of the unrolled plane
// (second order in the angle to the nearest feature: within 3% for points within 1 cm of a 20 cm
// tire, tests/test_tire_shape.cpp); inside, under a block's foot, it can underestimate the depth
// (a bound with the right sign and an outward normal). The sign is exact: membership is decided in
// the same coordinates that define the solid. Far from the tire (more than `kNear` tread depths
// outside the band) the distance of a bounding cylinder is returned: a lower bound with the right
// sign, so colliders, which act only on nodes with d <= 0, are unaffected, and grid nodes far from
// the tread cost a few flops.
#pragma once

#include <cmath>

#include "kernels/hd.hpp"

namespace firn {

constexpr int kMaxTreadBlocks = 12;
constexpr int kMaxBlockVertices = 4;

template <class T>
struct TreadBlock {
  int vertex_count = 0;
  T u[kMaxBlockVertices] = {};  // circumferential, in pitch lengths
  T w[kMaxBlockVertices] = {};  // lateral, in tire widths
  T u_lo = T(0), u_hi = T(0), w_lo = T(0), w_hi = T(0);  // the vertices' bounding box

  // Vertices are added through here, which keeps the bounding box.
  void add_vertex(T u_v, T w_v) {
    u_lo = vertex_count == 0 || u_v < u_lo ? u_v : u_lo;
    u_hi = vertex_count == 0 || u_v > u_hi ? u_v : u_hi;
    w_lo = vertex_count == 0 || w_v < w_lo ? w_v : w_lo;
    w_hi = vertex_count == 0 || w_v > w_hi ? w_v : w_hi;
    u[vertex_count] = u_v;
    w[vertex_count] = w_v;
    ++vertex_count;
  }
};

// Signed distance from p to a simple polygon (negative inside) and its gradient g: the nearest
// edge point gives the magnitude, the even-odd crossing rule the sign.
template <class T>
FIRN_HD T polygon_distance(const T* px, const T* py, int count, T x, T y, T g[2]) {
  T best = T(INFINITY), bx = T(0), by = T(0);
  bool inside = false;
  for (int i = 0, j = count - 1; i < count; j = i++) {
    const T ex = px[i] - px[j], ey = py[i] - py[j];
    const T wx = x - px[j], wy = y - py[j];
    T t = (wx * ex + wy * ey) / (ex * ex + ey * ey);
    t = t < T(0) ? T(0) : (t > T(1) ? T(1) : t);
    const T dx = wx - t * ex, dy = wy - t * ey, d2 = dx * dx + dy * dy;
    if (d2 < best) best = d2, bx = dx, by = dy;
    if ((py[i] > y) != (py[j] > y) && x < px[j] + (y - py[j]) * ex / ey) inside = !inside;
  }
  const T d = std::sqrt(best);
  const T s = inside ? T(-1) : T(1);
  g[0] = d > T(0) ? s * bx / d : T(0);
  g[1] = d > T(0) ? s * by / d : T(0);
  return s * d;
}

template <class T>
struct TireShape {
  T radius = T(0.2);        // outer radius R (top of the tread)
  T width = T(0.125);       // W
  T tread_depth = T(0.012);
  int pitches = 12;
  T shoulder = T(0);  // a slick tire's shoulder radius s (0: square shoulders)
  int block_count = 0;
  TreadBlock<T> blocks[kMaxTreadBlocks];

  // Beyond this many tread depths outside the band, the bounding cylinder's distance is returned.
  static constexpr T kNear = T(2);
  // A block is skipped when its bounding box lies farther than the best distance so far plus this
  // many tread depths (12 um for a 12 mm tread: far above the roundings of either distance).
  static constexpr T kSkipSlack = T(1e-3);

  // The distance from x to the interval [lo, hi], 0 inside it.
  FIRN_HD static T gap(T lo, T hi, T x) { return x < lo ? lo - x : (x > hi ? x - hi : T(0)); }

  // Signed distance at y (tire frame) and the outward unit normal n.
  FIRN_HD T distance(const T y[3], T n[3]) const {
    const T r = std::sqrt(y[0] * y[0] + y[1] * y[1]);
    const T er[3] = {r > T(0) ? y[0] / r : T(1), r > T(0) ? y[1] / r : T(0), T(0)};
    const T ephi[3] = {-er[1], er[0], T(0)};
    const T zs = y[2] < T(0) ? T(-1) : T(1);
    const T half = T(0.5) * width, inner = radius - tread_depth;

    // A capped cylinder of radius `rad` and half width `half`, its edges rounded to `round`: exact
    // distance and normal.
    auto cylinder = [&](T rad, T out[3], T round) {
      const T qr = r - (rad - round), qz = std::fabs(y[2]) - (half - round);
      if (qr > T(0) || qz > T(0)) {
        const T a = qr > T(0) ? qr : T(0), b = qz > T(0) ? qz : T(0), len = std::sqrt(a * a + b * b);
        for (int d = 0; d < 3; ++d) out[d] = (a * er[d]) / len;
        out[2] += b * zs / len;
        return len - round;
      }
      for (int d = 0; d < 3; ++d) out[d] = qr > qz ? er[d] : T(0);
      if (!(qr > qz)) out[2] = zs;
      return (qr > qz ? qr : qz) - round;
    };

    const T bound = cylinder(radius, n, block_count == 0 ? shoulder : T(0));
    if (bound > kNear * tread_depth || block_count == 0) return bound;  // far away, or a slick tire
    T best = cylinder(inner, n, T(0));

    // The tread: each block's polygon in the unrolled plane, extruded over r <= R. Below the band
    // the extrusion lies inside the carcass, so the union is unchanged, and a point in a block
    // near its foot sees the block's top and sides, not a face buried in the carcass.
    const T h = r - radius;
    const T pitch_angle = T(6.283185307179586) / T(pitches);
    T phi = std::atan2(y[1], y[0]);
    if (phi < T(0)) phi += T(6.283185307179586);
    const T k = std::floor(phi / pitch_angle);
    // Unrolled at rho = r inside the band (a block's side faces are radial planes, r dphi away) and
    // at rho = sqrt(r R) above it (the chord to the block's top edge, 2 sqrt(r R) sin(dphi / 2)).
    const T rho = r > radius ? std::sqrt(r * radius) : r;
    const T s = (phi - k * pitch_angle) * rho, pitch_length = pitch_angle * rho;
    for (int b = 0; b < block_count; ++b) {
      const TreadBlock<T>& blk = blocks[b];
      const T gz = gap(blk.w_lo * width, blk.w_hi * width, y[2]);
      for (int shift = -1; shift <= 1; ++shift) {
        // A block whose bounding box is farther than the best distance so far cannot win: outside
        // the box its distance is at least d2 >= the box's distance > 0. The slack keeps the skip on
        // the safe side of rounding, so the result is the one of testing every block.
        const T gs = gap((blk.u_lo + T(shift)) * pitch_length, (blk.u_hi + T(shift)) * pitch_length, s);
        const T box2 = gs * gs + gz * gz, reach = best + kSkipSlack * tread_depth;
        if (box2 > T(0) && (reach <= T(0) || box2 > reach * reach)) continue;
        T ps[kMaxBlockVertices], pz[kMaxBlockVertices], g[2];
        for (int v = 0; v < blk.vertex_count; ++v) {
          ps[v] = (blk.u[v] + T(shift)) * pitch_length;
          pz[v] = blk.w[v] * width;
        }
        const T d2 = polygon_distance(ps, pz, blk.vertex_count, s, y[2], g);
        T d, cs, ch;  // distance, and the weights of the in-plane and radial gradients
        if (d2 > T(0) || h > T(0)) {
          const T a = d2 > T(0) ? d2 : T(0), c = h > T(0) ? h : T(0);
          d = std::sqrt(a * a + c * c);
          cs = a / d, ch = c / d;
        } else {
          d = d2 > h ? d2 : h;
          cs = d2 > h ? T(1) : T(0), ch = T(1) - cs;
        }
        if (d < best) {
          best = d;
          for (int i = 0; i < 3; ++i) n[i] = cs * g[0] * ephi[i] + ch * er[i];
          n[2] += cs * g[1];
        }
      }
    }
    return best;
  }
};

// The same tire in another precision.
template <class T, class U>
TireShape<T> tire_shape_cast(const TireShape<U>& t) {
  TireShape<T> o;
  o.radius = T(t.radius);
  o.width = T(t.width);
  o.tread_depth = T(t.tread_depth);
  o.pitches = t.pitches;
  o.shoulder = T(t.shoulder);
  o.block_count = t.block_count;
  for (int b = 0; b < kMaxTreadBlocks; ++b)
    for (int v = 0; v < t.blocks[b].vertex_count; ++v) o.blocks[b].add_vertex(T(t.blocks[b].u[v]), T(t.blocks[b].w[v]));
  return o;
}

}  // namespace firn
