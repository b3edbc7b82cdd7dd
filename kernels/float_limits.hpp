// Floating-point limits usable in device code: std::numeric_limits<T>::epsilon() and max() are host
// functions under nvcc, so kernels read these constants (the same values, from <cfloat>) instead.
#pragma once

#include <cfloat>
#include <cstddef>
#include <cstdint>

namespace firn {

template <class T>
struct FloatLimits;

template <>
struct FloatLimits<float> {
  static constexpr float kEpsilon = FLT_EPSILON;
  static constexpr float kMax = FLT_MAX;
};

template <>
struct FloatLimits<double> {
  static constexpr double kEpsilon = DBL_EPSILON;
  static constexpr double kMax = DBL_MAX;
};

// "No particle": larger than every index.
constexpr std::size_t kNoParticle = SIZE_MAX;

}  // namespace firn
