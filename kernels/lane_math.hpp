// Elementary functions on Lanes (kernels/lanes.hpp) written as arithmetic the compiler vectorises,
// where the C library's sqrt, cbrt and pow are scalar calls (sqrt too: it may set errno, and
// -fno-math-errno would let the compiler rearrange the rest of the engine's arithmetic): the
// constitutive kernels' norms, J^(-1/3) and the power hardening law (issue 15). sqrt and
// inverse_cbrt are accurate to a few units in the last place of T,
// pow_lanes to a few units times its condition number 1 + |n ln x| (tests/test_lanes.cpp); pow_lanes
// reports the lanes outside the range it accepts, for the caller's scalar path.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include "kernels/hd.hpp"
#include "kernels/lanes.hpp"

namespace firn {

template <class T>
struct FloatBits;
template <>
struct FloatBits<float> {
  using Int = std::int32_t;
  static constexpr int kMantissa = 23, kBias = 127;
  // inverse_root's guesses of x^(-1/2) and x^(-1/3) from the bits, (1 + 1/K) (bias - 0.045)
  // 2^mantissa - bits(x) / K: the exponent field is a scaled log2 (Lomont 2003, "Fast inverse
  // square root"). Within 3.4% and 10%; Newton steps then square the error (times (K + 1) / 2):
  // 3.4e-2 -> 1.7e-3 -> 4.5e-6 -> 3e-11, and 0.1 -> 2e-2 -> 8e-4 -> 1e-6 -> 3e-12.
  static constexpr Int kInverseSqrtMagic = 0x5f3759df, kInverseCbrtMagic = 0x54a2fa8e;
  static constexpr int kInverseSqrtSteps = 3, kInverseCbrtSteps = 4;
  static constexpr int kLogTerms = 5, kExpDegree = 7;  // truncation below 3e-9 (see pow_lanes)
  static constexpr Int kSqrt2Mantissa = 0x3504f3;     // of sqrt(2) rounded to T
};
template <>
struct FloatBits<double> {
  using Int = std::int64_t;
  static constexpr int kMantissa = 52, kBias = 1023;
  static constexpr Int kInverseSqrtMagic = 0x5fe6eb50c7b537a9, kInverseCbrtMagic = 0x553f09fc6da44800;
  static constexpr int kInverseSqrtSteps = 4, kInverseCbrtSteps = 5;
  static constexpr int kLogTerms = 11, kExpDegree = 12;  // truncation below 1e-17
  static constexpr Int kSqrt2Mantissa = 0x6a09e667f3bcd;
};

template <class T>
FIRN_HD typename FloatBits<T>::Int bits_of(T x) {
  typename FloatBits<T>::Int i;
  std::memcpy(&i, &x, sizeof(T));
  return i;
}
template <class T>
FIRN_HD T from_bits(typename FloatBits<T>::Int i) {
  T x;
  std::memcpy(&x, &i, sizeof(T));
  return x;
}

// x^(-1/K), K = 2 or 3, for positive normal x: a guess from the bits, then Newton's method on
// y^-K = x, y <- y (K + 1 - x y^K) / K, which converges quadratically and divides by nothing. One
// value, for the body of a loop over lanes (FIRN_LANES), and on Lanes.
template <int K, class T>
FIRN_HD T inverse_root(T x) {
  static_assert(K == 2 || K == 3, "square and cube roots");
  using B = FloatBits<T>;
  constexpr typename B::Int kMagic = K == 2 ? B::kInverseSqrtMagic : B::kInverseCbrtMagic;
  constexpr int kSteps = K == 2 ? B::kInverseSqrtSteps : B::kInverseCbrtSteps;
  // bits / K through T: only a guess is wanted, so its rounding does not matter
  T y = from_bits<T>(kMagic - static_cast<typename B::Int>(T(bits_of(x)) * T(1.0 / K)));
  FIRN_UNROLL
  for (int s = 0; s < kSteps; ++s) {
    T xyk = x * y;  // x first: for x = 0 the guess's y^K would overflow to inf
    FIRN_UNROLL
    for (int k = 1; k < K; ++k) xyk = xyk * y;
    y = y * (T(K + 1) - xyk) * T(1.0 / K);
  }
  return y;
}
template <int K, class T, int W>
FIRN_HD Lanes<T, W> inverse_root(const Lanes<T, W>& x) {
  Lanes<T, W> y;
  FIRN_LANES
  for (int l = 0; l < W; ++l) y.v[l] = inverse_root<K>(x.v[l]);
  return y;
}

template <class T, int W>
FIRN_HD Lanes<T, W> inverse_cbrt(const Lanes<T, W>& x) {
  return inverse_root<3>(x);
}

// sqrt(x) for x >= 0, as x x^(-1/2); x = 0 gives 0 (its guess stays finite).
template <class T, int W>
FIRN_HD Lanes<T, W> sqrt(const Lanes<T, W>& x) {
  return x * inverse_root<2>(x);
}

// J^(-2/3), the isochoric factor of the hyperelastic laws: by the C library for one value, by
// inverse_cbrt on lanes.
template <class T>
FIRN_HD T pow_minus_two_thirds(T J) {
  return T(1) / (std::cbrt(J) * std::cbrt(J));
}
template <class T, int W>
FIRN_HD Lanes<T, W> pow_minus_two_thirds(const Lanes<T, W>& J) {
  const Lanes<T, W> y = inverse_cbrt(J);
  return y * y;
}

// x^n for x > 0, as exp(n ln x):
//   ln x = e ln 2 + 2 atanh(s), x = 2^e m with m in [sqrt(1/2), sqrt(2)), s = (m - 1) / (m + 1),
//     |s| <= 0.172, the series 2 (s + s^3/3 + s^5/5 + ...) (Abramowitz and Stegun 4.1.28);
//   exp y = 2^k exp(r), k the integer nearest y / ln 2, r = y - k ln 2 with ln 2 split in two parts
//     (Cody and Waite 1980) so that r is exact to T's rounding, |r| <= 0.347, exp(r) by its Taylor series.
// `ok` is cleared for lanes with x not positive and normal or |n ln x| too large for 2^k in T; their
// result is not defined.
template <class T, int W>
FIRN_HD Lanes<T, W> pow_lanes(const Lanes<T, W>& x, T n, LaneMask<W>& ok) {
  using B = FloatBits<T>;
  using Int = typename B::Int;
  constexpr T kLn2Hi = T(0.693145751953125), kLn2Lo = T(1.42860682030941723212e-6);
  constexpr T kMaxExponent = T(B::kBias - 2);
  Lanes<T, W> r;
  FIRN_LANES
  for (int l = 0; l < W; ++l) {
    const Int i = bits_of(x.v[l]);
    const Int e_field = i >> B::kMantissa;
    // Branch-free on integers, so that the loop stays one vector loop (a select between two
    // floating-point results becomes a branch under GCC's default -ftrapping-math).
    const bool normal = (e_field > 0) & (e_field < 2 * B::kBias + 1);  // also false for x <= 0 (sign bit)
    const Int mantissa = i & ((Int(1) << B::kMantissa) - 1);
    const Int high = mantissa > B::kSqrt2Mantissa ? 1 : 0;  // m above sqrt(2): halve it, exactly
    const T m = from_bits<T>((mantissa | (Int(B::kBias) << B::kMantissa)) - (high << B::kMantissa));
    const T e = T(e_field - B::kBias + high);
    const T s = (m - T(1)) / (m + T(1)), s2 = s * s;
    T series = T(1) / T(2 * B::kLogTerms - 1);
    FIRN_UNROLL
    for (int k = B::kLogTerms - 2; k >= 0; --k) series = series * s2 + T(1) / T(2 * k + 1);
    const T ln_x = e * kLn2Hi + (e * kLn2Lo + T(2) * s * series);
    const T y = n * ln_x;
    const T kf = y * T(1.44269504088896340736);
    const bool in_range = (kf < kMaxExponent) & (kf > -kMaxExponent);
    const T k_safe = from_bits<T>(bits_of(kf) & -Int(in_range));  // 0 out of range (and for NaN)
    const Int k = static_cast<Int>(k_safe + std::copysign(T(0.5), k_safe));
    const T rem = (y - T(k) * kLn2Hi) - T(k) * kLn2Lo;
    T p = T(1);
    FIRN_UNROLL
    for (int d = B::kExpDegree; d >= 1; --d) p = T(1) + p * rem * (T(1) / T(d));
    r.v[l] = p * from_bits<T>((k + B::kBias) << B::kMantissa);
    ok.m[l] = ok.m[l] & normal & in_range;
  }
  return r;
}

}  // namespace firn
