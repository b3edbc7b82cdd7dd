// Bisection for the largest value of a parameter at which a run still succeeds (the largest stable
// CFL number, the highest impact speed a snowball survives), assuming success is monotone: every
// value below a success succeeds. The bracket's ends are tried first, so an answer outside it is
// reported as such rather than clipped silently.
#pragma once

#include <functional>
#include <optional>
#include <vector>

namespace firn::study {

struct BisectionSettings {
  double lo = 0, hi = 1;     // the bracket searched
  double tolerance = 0.01;   // stop when hi - lo (or hi / lo - 1 when geometric) is at most this
  bool geometric = false;    // midpoints sqrt(lo hi): for a bracket spanning decades (speeds)
};

struct BisectionTrial {
  double value;
  bool ok;
};

struct BisectionResult {
  std::optional<double> largest_ok;     // none: even settings.lo failed
  std::optional<double> smallest_fail;  // none: even settings.hi succeeded
  std::vector<BisectionTrial> trials;   // in the order they ran
};

// Calls ok(value) at hi, then lo, then midpoints until the bracket [largest_ok, smallest_fail] is
// within the tolerance. Throws std::invalid_argument for an empty bracket or a tolerance <= 0.
BisectionResult bisect_largest_ok(const BisectionSettings& settings, const std::function<bool(double)>& ok);

}  // namespace firn::study
