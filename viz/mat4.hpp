// Small column-major 4x4 matrices and 3-vectors for cameras, in the layout OpenGL uploads
// (glUniformMatrix4fv with transpose = GL_FALSE). Formulas: the OpenGL Programming Guide,
// appendix E (gluLookAt, gluPerspective, glOrtho).
#pragma once

#include <array>
#include <cmath>

namespace firn::viz {

using Vec3 = std::array<double, 3>;

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double dot(Vec3 a, Vec3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(Vec3 a) { return (1 / length(a)) * a; }

struct Mat4 {
  std::array<float, 16> m{};  // column-major: m[column * 4 + row]
  float& at(int row, int col) { return m[std::size_t(col * 4 + row)]; }
  float at(int row, int col) const { return m[std::size_t(col * 4 + row)]; }
  static Mat4 identity() {
    Mat4 r;
    for (int i = 0; i < 4; ++i) r.at(i, i) = 1;
    return r;
  }
};

inline Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      float s = 0;
      for (int k = 0; k < 4; ++k) s += a.at(i, k) * b.at(k, j);
      r.at(i, j) = s;
    }
  return r;
}

// gluLookAt: the view matrix of an eye at `eye` looking at `target`.
inline Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up) {
  const Vec3 f = normalize(target - eye), s = normalize(cross(f, up)), u = cross(s, f);
  Mat4 r = Mat4::identity();
  for (int c = 0; c < 3; ++c) {
    r.at(0, c) = float(s[std::size_t(c)]);
    r.at(1, c) = float(u[std::size_t(c)]);
    r.at(2, c) = float(-f[std::size_t(c)]);
  }
  r.at(0, 3) = float(-dot(s, eye));
  r.at(1, 3) = float(-dot(u, eye));
  r.at(2, 3) = float(dot(f, eye));
  return r;
}

// gluPerspective with the vertical field of view in radians.
inline Mat4 perspective(double fovy, double aspect, double near, double far) {
  const double f = 1 / std::tan(fovy / 2);
  Mat4 r;
  r.at(0, 0) = float(f / aspect);
  r.at(1, 1) = float(f);
  r.at(2, 2) = float((far + near) / (near - far));
  r.at(2, 3) = float(2 * far * near / (near - far));
  r.at(3, 2) = -1;
  return r;
}

// glOrtho.
inline Mat4 orthographic(double l, double r, double b, double t, double n, double f) {
  Mat4 m = Mat4::identity();
  m.at(0, 0) = float(2 / (r - l));
  m.at(1, 1) = float(2 / (t - b));
  m.at(2, 2) = float(-2 / (f - n));
  m.at(0, 3) = float(-(r + l) / (r - l));
  m.at(1, 3) = float(-(t + b) / (t - b));
  m.at(2, 3) = float(-(f + n) / (f - n));
  return m;
}

}  // namespace firn::viz

namespace firn::viz {

// Inverse of a rigid transform [R t; 0 1]: [R^T, -R^T t; 0 1].
inline Mat4 inverse_rigid(const Mat4& a) {
  Mat4 r = Mat4::identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.at(i, j) = a.at(j, i);
  for (int i = 0; i < 3; ++i) r.at(i, 3) = -(r.at(i, 0) * a.at(0, 3) + r.at(i, 1) * a.at(1, 3) + r.at(i, 2) * a.at(2, 3));
  return r;
}

// The direction d transformed by the rotation part of a.
inline Vec3 rotate(const Mat4& a, const Vec3& d) {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[std::size_t(i)] = a.at(i, 0) * d[0] + a.at(i, 1) * d[1] + a.at(i, 2) * d[2];
  return r;
}

}  // namespace firn::viz
