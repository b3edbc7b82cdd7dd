// The combines of parallel_reduce as device-callable functors: combine(a, b) merges partial b
// into a. std::max / std::min are constexpr, hence callable in device code under
// --expt-relaxed-constexpr.
#pragma once

#include <algorithm>

#include "kernels/hd.hpp"

namespace firn {

struct Sum {
  template <class R>
  FIRN_HD void operator()(R& a, const R& b) const {
    a += b;
  }
};

struct Max {
  template <class R>
  FIRN_HD void operator()(R& a, const R& b) const {
    a = std::max(a, b);
  }
};

struct Min {
  template <class R>
  FIRN_HD void operator()(R& a, const R& b) const {
    a = std::min(a, b);
  }
};

struct BitOr {
  template <class R>
  FIRN_HD void operator()(R& a, const R& b) const {
    a |= b;
  }
};

}  // namespace firn
