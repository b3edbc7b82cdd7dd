// Least-squares fits over the samples with t0 <= t <= t1: a constant (the window's mean) and a
// straight line y = a + b t, whose slope is b = cov(t, y) / var(t) (the normal equations of the
// fit, e.g. Press et al., Numerical Recipes, section 15.2). NaN when the window holds no sample
// (the mean) or fewer than two distinct times (the slope).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace firn {

inline double window_mean(const std::vector<double>& t, const std::vector<double>& y, double t0, double t1) {
  double n = 0, sum = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t0 && t[i] <= t1) {
      n += 1;
      sum += y[i];
    }
  return n > 0 ? sum / n : NAN;
}

inline double least_squares_slope(const std::vector<double>& t, const std::vector<double>& y, double t0, double t1) {
  const double mean_t = window_mean(t, t, t0, t1), mean_y = window_mean(t, y, t0, t1);
  double cov = 0, var = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t0 && t[i] <= t1) {
      cov += (t[i] - mean_t) * (y[i] - mean_y);
      var += (t[i] - mean_t) * (t[i] - mean_t);
    }
  return var > 0 ? cov / var : NAN;
}

}  // namespace firn
