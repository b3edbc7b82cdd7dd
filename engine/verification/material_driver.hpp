// Material-point driver (DESIGN.md section 6, problem 5): one constitutive model, in double
// precision, along a homogeneous deformation path F(t), t in [0, 1], in N increments. Each increment
// applies the engine's update to the model's F (the elastic F_E for plastic models),
//   F_E <- (F_{k+1} F_k^{-1}) F_E,
// then the return mapping (plastic models) and the Kirchhoff stress, exactly as step 2 of the
// engine's step does for one particle.
#pragma once

#include <functional>
#include <vector>

#include "engine/materials.hpp"
#include "kernels/mat3.hpp"

namespace firn {

// Histories at t_k = k / N, k = 0..N (entry 0: the start, before any increment).
struct DriverHistory {
  std::vector<Mat3<double>> F;    // total deformation gradient
  std::vector<Mat3<double>> F_E;  // the model's F after the return
  std::vector<Mat3<double>> tau;  // Kirchhoff stress
  std::vector<PlasticState<double>> state;
  // The return mappings' plastic work per unit rest volume since the start, sum W(F_trial) -
  // W(F_returned) (kernels/step/constitutive_update.hpp).
  std::vector<double> plastic_work;
};

using DeformationPath = std::function<Mat3<double>(double t)>;

DriverHistory drive_material(const MaterialModel<double>& model, const DeformationPath& path, int increments);

// Uniaxial stress: F = diag(1 + axial_strain t, l, l) with the lateral stretch l found at every
// increment by Newton iteration (finite-difference slope) until the lateral stress tau_yy vanishes
// to 1e-12 of the axial stress.
DriverHistory drive_uniaxial_stress(const MaterialModel<double>& model, double axial_strain, int increments);

namespace paths {
DeformationPath uniaxial_strain(double strain);  // diag(1 + strain t, 1, 1)
DeformationPath simple_shear(double gamma);      // I + gamma t e_x e_y^T
// J^(1/3) I with J from 1 down to J_min at t = 1/2 and back to 1.
DeformationPath hydrostatic_cycle(double J_min);
// J(t)^(1/3) (I + gamma t e_x e_y^T), J(t) = 1 + (J_min - 1) t: compaction with shear.
DeformationPath compress_and_shear(double J_min, double gamma);
// diag(1 + amplitude sin(2 pi cycles t), 1, 1).
DeformationPath cyclic_uniaxial_strain(double amplitude, int cycles);
// Q(t) F(t) with Q(t) the rotation by angle t about axis: a superposed rigid rotation.
DeformationPath rotated(const DeformationPath& path, const Vec3<double>& axis, double angle);
}  // namespace paths

}  // namespace firn
