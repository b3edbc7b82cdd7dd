// Least-squares straight-line fit y = a + b t: the slope b = cov(t, y) / var(t) over the samples
// with t0 <= t <= t1 (the normal equations of the fit, e.g. Press et al., Numerical Recipes,
// section 15.2). NaN when fewer than two distinct times fall in the window.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace firn {

inline double least_squares_slope(const std::vector<double>& t, const std::vector<double>& y, double t0, double t1) {
  double n = 0, mean_t = 0, mean_y = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t0 && t[i] <= t1) {
      n += 1;
      mean_t += t[i];
      mean_y += y[i];
    }
  if (n < 2) return NAN;
  mean_t /= n;
  mean_y /= n;
  double cov = 0, var = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t0 && t[i] <= t1) {
      cov += (t[i] - mean_t) * (y[i] - mean_y);
      var += (t[i] - mean_t) * (t[i] - mean_t);
    }
  return var > 0 ? cov / var : NAN;
}

}  // namespace firn
