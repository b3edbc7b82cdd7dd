// A collider as the engine keeps it: its shape and pose in double precision, how it moves, and
// the grid's reaction on it (DESIGN.md section 3, "Colliders").
//
// Motion, advanced once per step before the grid update so the nodes see the end-of-step pose:
//   prescribed: constant velocity and angular velocity;
//   loaded_axle: the angular velocity is prescribed, and the body moves along the world y axis as
//     one rigid degree of freedom under a constant downward load L and the grid's reaction F_y
//     from the previous step: m dv_y/dt = F_y - L (semi-implicit Euler: velocity, then position).
//     L is the whole vertical load on the axle, the tire's own weight included (issue 5, "Axle").
// Spin, independent of the motion above:
//   prescribed (free_spin false): the angular velocity stays as given;
//   free_spin: the angular velocity about the world z axis (a tire's axle; the body turns only about
//     it) is one rigid degree of freedom under the grid's torque T_z about the centre from the
//     previous step and no applied torque (a towed, free-rolling wheel): I dw_z/dt = T_z, integrated
//     like the loaded axle (semi-implicit Euler: angular velocity, then rotation).
// Rotation: R <- Rot(omega dt) R (Rodrigues, kernels/mat3.hpp), in double.
#pragma once

#include <cmath>

#include "engine/state_stream.hpp"
#include "kernels/colliders.hpp"
#include "kernels/mat3.hpp"

namespace firn {

struct ColliderBody {
  enum class Motion { prescribed, loaded_axle };

  Collider<double> collider;
  Motion motion = Motion::prescribed;
  double mass = 0;  // loaded_axle
  double load = 0;  // loaded_axle: downward force on the axle (N)
  bool free_spin = false;
  double inertia = 0;  // free_spin: moment of inertia about the z axis through the centre (kg m^2)
  double penalty_stiffness = 1;  // contact penalty: omega = penalty_stiffness c / dx (kernels/step/penalty_contact.hpp)

  // Reaction of the grid on the collider in the last step (N, N m about collider.center), and its
  // time integral since the last reset_impulse().
  double force[3] = {0, 0, 0}, torque[3] = {0, 0, 0};
  double impulse[3] = {0, 0, 0}, angular_impulse[3] = {0, 0, 0};
  double impulse_time = 0;

  ColliderBody() = default;
  ColliderBody(const Collider<double>& c) : collider(c) {}  // NOLINT: a collider moving as prescribed

  void advance(double dt) {
    Collider<double>& c = collider;
    if (motion == Motion::loaded_axle) c.velocity[1] += dt * (force[1] - load) / mass;
    if (free_spin) c.angular_velocity[2] += dt * torque[2] / inertia;
    for (int d = 0; d < 3; ++d) c.center[d] += dt * c.velocity[d];
    const Vec3<double> w = {{c.angular_velocity[0], c.angular_velocity[1], c.angular_velocity[2]}};
    const double speed = norm(w);
    if (speed > 0) {
      const Mat3<double> q = axis_angle_rotation(w, speed * dt);
      Mat3<double> r;
      for (int i = 0; i < 9; ++i) r.m[i] = c.rotation[i];
      r = q * r;
      for (int i = 0; i < 9; ++i) c.rotation[i] = r.m[i];
    }
  }

  void reset_impulse() {
    for (int d = 0; d < 3; ++d) impulse[d] = angular_impulse[d] = 0;
    impulse_time = 0;
  }

  // Records the reaction of one step of length dt.
  void add_reaction(const double f[3], const double t[3], double dt) {
    for (int d = 0; d < 3; ++d) {
      force[d] = f[d];
      torque[d] = t[d];
      impulse[d] += f[d] * dt;
      angular_impulse[d] += t[d] * dt;
    }
    impulse_time += dt;
  }

  // What moves and accumulates (pose, velocities, reactions), for checkpoints; the shape, its
  // motion type, mass, load, spin type and inertia come from the scene.
  void save_motion(StateWriter& out) const { motion_fields(out, *this); }
  void load_motion(StateReader& in) { motion_fields(in, *this); }

 private:
  template <class Stream, class Body>
  static void motion_fields(Stream& s, Body& b) {
    s.field(b.collider.center);
    s.field(b.collider.rotation);
    s.field(b.collider.velocity);
    s.field(b.collider.angular_velocity);
    s.field(b.force);
    s.field(b.torque);
    s.field(b.impulse);
    s.field(b.angular_impulse);
    s.field(b.impulse_time);
  }
};

}  // namespace firn
