#include "engine/scene/body_shape.hpp"

#include <algorithm>

namespace firn {

bool BodyShape::contains(const Point& p) const {
  switch (kind) {
    case Kind::sphere: {
      const double a = p[0] - center[0], b = p[1] - center[1], c = p[2] - center[2];
      return a * a + b * b + c * c < radius * radius;
    }
    case Kind::box:
      return p[0] >= min[0] && p[0] < max[0] && p[1] >= min[1] && p[1] < max[1] && p[2] >= min[2] && p[2] < max[2];
    case Kind::cylinder: {
      double r2 = 0;
      for (int d = 0; d < 3; ++d)
        if (d != axis) r2 += (p[d] - center[d]) * (p[d] - center[d]);
      return r2 < radius * radius && std::abs(p[axis] - center[axis]) < 0.5 * length;
    }
    case Kind::union_of:
      return std::any_of(parts.begin(), parts.end(), [&](const BodyShape& s) { return s.contains(p); });
    case Kind::difference_of:
      return !parts.empty() && parts[0].contains(p) &&
             std::none_of(parts.begin() + 1, parts.end(), [&](const BodyShape& s) { return s.contains(p); });
  }
  return false;
}

void BodyShape::bounds(Point& lo, Point& hi) const {
  switch (kind) {
    case Kind::sphere:
      for (int d = 0; d < 3; ++d) lo[d] = center[d] - radius, hi[d] = center[d] + radius;
      return;
    case Kind::box:
      lo = min, hi = max;
      return;
    case Kind::cylinder:
      for (int d = 0; d < 3; ++d) {
        const double h = d == axis ? 0.5 * length : radius;
        lo[d] = center[d] - h, hi[d] = center[d] + h;
      }
      return;
    case Kind::union_of:
    case Kind::difference_of: {
      if (parts.empty()) {
        lo = hi = {0, 0, 0};
        return;
      }
      parts[0].bounds(lo, hi);
      if (kind == Kind::difference_of) return;  // never larger than its first part
      for (std::size_t i = 1; i < parts.size(); ++i) {
        Point l, h;
        parts[i].bounds(l, h);
        for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], l[d]), hi[d] = std::max(hi[d], h[d]);
      }
      return;
    }
  }
}

}  // namespace firn
