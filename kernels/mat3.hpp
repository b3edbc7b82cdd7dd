// Small fixed-size vector and matrix types usable on host and device.
// Row-major 3x3; every function is FIRN_HD and allocation-free.
#pragma once

#include <cmath>

#include "kernels/hd.hpp"

namespace firn {

template <class T>
struct Vec3 {
  T v[3];
  FIRN_HD T& operator[](int i) { return v[i]; }
  FIRN_HD const T& operator[](int i) const { return v[i]; }
};

template <class T>
struct Mat3 {
  T m[9];  // row-major: m[3 * r + c]
  FIRN_HD T& operator()(int r, int c) { return m[3 * r + c]; }
  FIRN_HD const T& operator()(int r, int c) const { return m[3 * r + c]; }

  FIRN_HD static Mat3 zero() { return Mat3{{T(0), T(0), T(0), T(0), T(0), T(0), T(0), T(0), T(0)}}; }
  FIRN_HD static Mat3 identity() { return diag(T(1), T(1), T(1)); }
  FIRN_HD static Mat3 diag(T a, T b, T c) { return Mat3{{a, T(0), T(0), T(0), b, T(0), T(0), T(0), c}}; }
};

template <class T>
FIRN_HD Vec3<T> operator+(const Vec3<T>& a, const Vec3<T>& b) { return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}}; }
template <class T>
FIRN_HD Vec3<T> operator-(const Vec3<T>& a, const Vec3<T>& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
template <class T>
FIRN_HD Vec3<T> operator*(T s, const Vec3<T>& a) { return {{s * a[0], s * a[1], s * a[2]}}; }
template <class T>
FIRN_HD T dot(const Vec3<T>& a, const Vec3<T>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
template <class T>
FIRN_HD Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
template <class T>
FIRN_HD T norm(const Vec3<T>& a) { return std::sqrt(dot(a, a)); }

template <class T>
FIRN_HD Mat3<T> operator+(const Mat3<T>& a, const Mat3<T>& b) {
  Mat3<T> r;
  for (int i = 0; i < 9; ++i) r.m[i] = a.m[i] + b.m[i];
  return r;
}
template <class T>
FIRN_HD Mat3<T> operator-(const Mat3<T>& a, const Mat3<T>& b) {
  Mat3<T> r;
  for (int i = 0; i < 9; ++i) r.m[i] = a.m[i] - b.m[i];
  return r;
}
template <class T>
FIRN_HD Mat3<T> operator*(T s, const Mat3<T>& a) {
  Mat3<T> r;
  for (int i = 0; i < 9; ++i) r.m[i] = s * a.m[i];
  return r;
}
template <class T>
FIRN_HD Mat3<T> operator*(const Mat3<T>& a, const Mat3<T>& b) {
  Mat3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = a(i, 0) * b(0, j) + a(i, 1) * b(1, j) + a(i, 2) * b(2, j);
  return r;
}
template <class T>
FIRN_HD Vec3<T> operator*(const Mat3<T>& a, const Vec3<T>& x) {
  return {{a(0, 0) * x[0] + a(0, 1) * x[1] + a(0, 2) * x[2], a(1, 0) * x[0] + a(1, 1) * x[1] + a(1, 2) * x[2],
           a(2, 0) * x[0] + a(2, 1) * x[1] + a(2, 2) * x[2]}};
}
template <class T>
FIRN_HD Mat3<T> transpose(const Mat3<T>& a) {
  return Mat3<T>{{a(0, 0), a(1, 0), a(2, 0), a(0, 1), a(1, 1), a(2, 1), a(0, 2), a(1, 2), a(2, 2)}};
}
// a * b^T without forming the transpose.
template <class T>
FIRN_HD Mat3<T> mul_transposed(const Mat3<T>& a, const Mat3<T>& b) {
  Mat3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = a(i, 0) * b(j, 0) + a(i, 1) * b(j, 1) + a(i, 2) * b(j, 2);
  return r;
}
template <class T>
FIRN_HD T determinant(const Mat3<T>& a) {
  return a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)) - a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0)) +
         a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0));
}
// The same two on a matrix held as 9 scalars row by row, as a loop over lanes keeps one lane's
// matrices: (a a^T)(r, c), the dot product of rows r and c, and det a. GCC 12 vectorises such a loop
// (kernels/hd.hpp, FIRN_NOINLINE) with the array passed by reference as here, but not with a Mat3
// local or with the array passed as a pointer ("no vectype for stmt").
template <class T>
FIRN_HD T rows_dot(const T (&a)[9], int r, int c) {
  return a[3 * r] * a[3 * c] + a[3 * r + 1] * a[3 * c + 1] + a[3 * r + 2] * a[3 * c + 2];
}
template <class T>
FIRN_HD T determinant_of_rows(const T (&a)[9]) {
  return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) + a[2] * (a[3] * a[7] - a[4] * a[6]);
}
// a^{-1} as adjugate / det (no check for singular a).
template <class T>
FIRN_HD Mat3<T> inverse(const Mat3<T>& a) {
  const T inv_det = T(1) / determinant(a);
  Mat3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      r(i, j) = (a(j1, i1) * a(j2, i2) - a(j1, i2) * a(j2, i1)) * inv_det;  // cofactor of a(j, i)
    }
  return r;
}
template <class T>
FIRN_HD T trace(const Mat3<T>& a) { return a(0, 0) + a(1, 1) + a(2, 2); }
// The rotation by `angle` about `axis` (any length), Rodrigues' formula.
template <class T>
FIRN_HD Mat3<T> axis_angle_rotation(const Vec3<T>& axis, T angle) {
  const T n = norm(axis);
  const Vec3<T> a = {{axis[0] / n, axis[1] / n, axis[2] / n}};
  const T c = std::cos(angle), s = std::sin(angle), t = T(1) - c;
  return Mat3<T>{{t * a[0] * a[0] + c, t * a[0] * a[1] - s * a[2], t * a[0] * a[2] + s * a[1],
                  t * a[0] * a[1] + s * a[2], t * a[1] * a[1] + c, t * a[1] * a[2] - s * a[0],
                  t * a[0] * a[2] - s * a[1], t * a[1] * a[2] + s * a[0], t * a[2] * a[2] + c}};
}
// Frobenius inner product A : B.
template <class T>
FIRN_HD T ddot(const Mat3<T>& a, const Mat3<T>& b) {
  T s = T(0);
  for (int i = 0; i < 9; ++i) s += a.m[i] * b.m[i];
  return s;
}

}  // namespace firn
