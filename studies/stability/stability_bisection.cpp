#include "studies/stability/stability_bisection.hpp"

#include <cmath>
#include <stdexcept>

namespace firn::study {

BisectionResult bisect_largest_ok(const BisectionSettings& s, const std::function<bool(double)>& ok) {
  if (!(s.lo < s.hi) || (s.geometric && !(s.lo > 0)))
    throw std::invalid_argument("bisection: the bracket must satisfy 0 < lo < hi (lo < hi when not geometric)");
  if (!(s.tolerance > 0)) throw std::invalid_argument("bisection: the tolerance must be positive");
  BisectionResult r;
  auto trial = [&](double v) {
    const bool good = ok(v);
    r.trials.push_back({v, good});
    return good;
  };
  if (trial(s.hi)) {
    r.largest_ok = s.hi;
    return r;
  }
  r.smallest_fail = s.hi;
  if (!trial(s.lo)) {
    r.smallest_fail = s.lo;
    return r;
  }
  double lo = s.lo, hi = s.hi;
  const auto width = [&] { return s.geometric ? hi / lo - 1 : hi - lo; };
  while (width() > s.tolerance) {
    const double mid = s.geometric ? std::sqrt(lo * hi) : 0.5 * (lo + hi);
    (trial(mid) ? lo : hi) = mid;
  }
  r.largest_ok = lo;
  r.smallest_fail = hi;
  return r;
}

}  // namespace firn::study
