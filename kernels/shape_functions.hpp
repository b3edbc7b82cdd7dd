// B-spline shape functions on a grid of spacing dx, in grid units X = (x - origin) / dx.
// A particle touches kSupport nodes per axis starting at base(X) = floor(X - kOffset); f = X - base.
// D^-1 = kDinv / dx^2 is the APIC/MLS inertia-like tensor inverse (Jiang et al. 2015, Sec. 5.3;
// Hu et al. 2018, Eq. 9): 4/dx^2 for quadratic and 3/dx^2 for cubic B-splines.
#pragma once

#include "kernels/hd.hpp"

namespace firn {

enum class Shape { quadratic, cubic };

template <class T>
struct QuadraticBSpline {
  static constexpr int kSupport = 3;
  static constexpr T kDinv = T(4);
  static constexpr T kOffset = T(0.5);
  // Truncation is floor because binning guarantees X >= kOffset.
  FIRN_HD static int base(T X) { return static_cast<int>(X - kOffset); }
  // f in [0.5, 1.5): N(1.5 - f), N(1 - f), N(0.5 - f) ... written with the distances to the nodes,
  // node c's weight at w[c stride] (the stencil keeps the axes as lanes: stride 4).
  FIRN_HD static void weights(T f, T* w, int stride = 1) {
    const T a = T(1.5) - f, b = f - T(1), c = f - T(0.5);
    w[0] = T(0.5) * a * a;
    w[stride] = T(0.75) - b * b;
    w[2 * stride] = T(0.5) * c * c;
  }
};

template <class T>
struct CubicBSpline {
  static constexpr int kSupport = 4;
  static constexpr T kDinv = T(3);
  static constexpr T kOffset = T(1);
  // Truncation is floor because binning guarantees X >= kOffset.
  FIRN_HD static int base(T X) { return static_cast<int>(X - kOffset); }
  // f in [1, 2): node distances f, f-1, 2-f, 3-f with N(d) = (2-d)^3/6 for 1 <= d < 2 and
  // d^3/2 - d^2 + 2/3 for 0 <= d < 1 (the cubic B-spline, Steffen et al. 2008); node c's weight at
  // w[c stride].
  FIRN_HD static void weights(T f, T* w, int stride = 1) {
    const T d1 = f - T(1), d2 = T(2) - f;  // distances to the two inner nodes, in [0, 1]
    const T o0 = T(2) - f, o3 = f - T(1);  // 2 - distance for the outer nodes (distance f and 3 - f)
    w[0] = o0 * o0 * o0 / T(6);
    w[stride] = T(0.5) * d1 * d1 * d1 - d1 * d1 + T(2) / T(3);
    w[2 * stride] = T(0.5) * d2 * d2 * d2 - d2 * d2 + T(2) / T(3);
    w[3 * stride] = o3 * o3 * o3 / T(6);
  }
};

template <class T, Shape S>
struct ShapeOf;
template <class T>
struct ShapeOf<T, Shape::quadratic> {
  using type = QuadraticBSpline<T>;
};
template <class T>
struct ShapeOf<T, Shape::cubic> {
  using type = CubicBSpline<T>;
};

}  // namespace firn
