#include "engine/verification/material_driver.hpp"

#include <cmath>
#include <type_traits>
#include <variant>

#include "kernels/step/constitutive_update.hpp"

namespace firn {
namespace {

// One increment of one material point: the model's F, then project (plastic models) and stress.
struct Point {
  Mat3<double> F_E = Mat3<double>::identity();
  PlasticState<double> state;
  Mat3<double> tau = Mat3<double>::zero();
  double plastic_work = 0;  // per unit rest volume, since the start

  void advance(const MaterialModel<double>& model, const Mat3<double>& increment) {
    F_E = increment * F_E;
    std::visit(
        [&](const auto& m) {
          using Model = std::decay_t<decltype(m)>;
          if constexpr (Model::kPlastic) project_measuring_work(m, F_E, state, &plastic_work);
          tau = m.kirchhoff(F_E, state);
        },
        model);
  }
};

void record(DriverHistory& h, const Mat3<double>& F, const Point& p) {
  h.F.push_back(F);
  h.F_E.push_back(p.F_E);
  h.tau.push_back(p.tau);
  h.state.push_back(p.state);
  h.plastic_work.push_back(p.plastic_work);
}

}  // namespace

DriverHistory drive_material(const MaterialModel<double>& model, const DeformationPath& path, int increments) {
  DriverHistory h;
  Point p;
  Mat3<double> F = path(0);
  p.advance(model, F);  // from the reference state to F(0) (the identity for every path here)
  record(h, F, p);
  for (int k = 1; k <= increments; ++k) {
    const Mat3<double> next = path(double(k) / increments);
    p.advance(model, next * inverse(F));
    F = next;
    record(h, F, p);
  }
  return h;
}

DriverHistory drive_uniaxial_stress(const MaterialModel<double>& model, double axial_strain, int increments) {
  DriverHistory h;
  Point p;
  Mat3<double> F = Mat3<double>::identity();
  p.advance(model, F);
  record(h, F, p);
  const auto trial = [&](double a, double l) {
    Point q = p;
    q.advance(model, Mat3<double>::diag(a, l, l) * inverse(F));
    return q;
  };
  for (int k = 1; k <= increments; ++k) {
    const double a = 1 + axial_strain * double(k) / increments;
    double l = F(1, 1);
    Point q = trial(a, l);
    for (int it = 0; it < 50 && std::abs(q.tau(1, 1)) > 1e-12 * std::abs(q.tau(0, 0)); ++it) {
      const double dl = 1e-7 * l;
      const double slope = (trial(a, l + dl).tau(1, 1) - q.tau(1, 1)) / dl;
      l -= q.tau(1, 1) / slope;
      q = trial(a, l);
    }
    p = q;
    F = Mat3<double>::diag(a, l, l);
    record(h, F, p);
  }
  return h;
}

namespace paths {

DeformationPath uniaxial_strain(double strain) {
  return [=](double t) { return Mat3<double>::diag(1 + strain * t, 1, 1); };
}

DeformationPath simple_shear(double gamma) {
  return [=](double t) {
    Mat3<double> F = Mat3<double>::identity();
    F(0, 1) = gamma * t;
    return F;
  };
}

DeformationPath hydrostatic_cycle(double J_min) {
  return [=](double t) {
    const double J = 1 + (J_min - 1) * (1 - std::abs(1 - 2 * t));
    const double s = std::cbrt(J);
    return Mat3<double>::diag(s, s, s);
  };
}

DeformationPath compress_and_shear(double J_min, double gamma) {
  return [=](double t) { return std::cbrt(1 + (J_min - 1) * t) * simple_shear(gamma)(t); };
}

DeformationPath cyclic_uniaxial_strain(double amplitude, int cycles) {
  return [=](double t) { return Mat3<double>::diag(1 + amplitude * std::sin(2 * M_PI * cycles * t), 1, 1); };
}

DeformationPath rotated(const DeformationPath& path, const Vec3<double>& axis, double angle) {
  return [=](double t) { return axis_angle_rotation(axis, angle * t) * path(t); };
}

}  // namespace paths
}  // namespace firn
