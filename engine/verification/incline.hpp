// A body released on the incline of DESIGN.md section 6, problem 4, shared by incline_sliding.cpp
// and incline_rolling.cpp. The slope is modelled by tilting gravity rather than the ground:
// g = g0 (sin theta, -cos theta, 0) over a horizontal plane collider (the solid y <= 0, boundary
// `separate`, Coulomb friction mu), which is the same problem seen in the slope's frame. The ground
// is then grid-aligned: every node at y <= 0 is inside it, with the exact normal (0, 1, 0), and the
// body's lattice of particles is flush with it, so the only discretisation in the contact is MPM's
// own. A tilted plane would put the contact on a staircase of nodes at varying depths and the body
// on a lattice at an angle to the grid: a test of the collider's pose, not of the friction law.
// Plane strain: the body is a slab one cell thick in z, and slip walls on every z node keep
// v_z = 0. Gravity is eased in, g(t) = g0 (1 - cos(pi t / ramp)) / 2 for t < ramp, as a body
// acceleration, so that the contact is loaded without a jolt (a sudden load sets the body bouncing
// on its contact; APIC hardly damps it).
#pragma once

#include <functional>
#include <vector>

#include "engine/materials.hpp"
#include "engine/particle_fill.hpp"
#include "engine/verification/verification.hpp"
#include "kernels/colliders.hpp"

namespace firn {

struct InclineRun {
  double angle = 0;      // theta (rad)
  double mu = 0;         // Coulomb coefficient of the ground
  double dx = 0;
  int per_cell = 2;      // particles per cell per axis
  MaterialInfo material;
  Point body_max = {0, 0, 0};  // the body lies in [0, body_max] in x and y, its lowest point on y = 0
  std::function<bool(const Point&)> inside;
  double travel = 0;     // room down the slope beyond body_max[0] (m)
  double ramp = 0;       // gravity eased in over this time (s)
  double end_time = 0;
  VerificationMethod method;
  ColliderContact contact = ColliderContact::nodes;  // the ground's
};

// Motion of the body's centre of mass, one sample per step.
struct InclineHistory {
  std::vector<double> time;
  std::vector<double> velocity;  // down the slope (m/s)
  std::vector<double> spin;      // angular velocity about -z, positive when rolling down (rad/s)
  // The ground's force on the body (N): along the slope and normal to it; and its moment (N m)
  // about the ground point below the centre of mass, whose normal force acts a lever arm
  // moment / normal_force ahead of that point (the friction has no arm about it where it acts on
  // the ground's surface row, as a pooled ground's does; on a node-by-node ground it acts on the
  // nodes one cell inside, so a small arm, dx friction / normal_force, is counted in).
  std::vector<double> ground_force, normal_force, ground_moment;
  long steps = 0;
  std::size_t particles = 0;
  double seconds = 0;  // wall time of the steps
};

InclineHistory run_incline(const InclineRun& run, const VerificationOptions& options);

// The sliding block of incline_sliding.cpp at dx = 0.02 / 2^level: 0.2 m by 0.05 m on 30 degrees,
// mu = 0.3.
InclineRun incline_sliding_block(int level, const VerificationMethod& method);

// g0 = 9.81 m/s^2.
constexpr double kInclineGravity = 9.81;

}  // namespace firn
