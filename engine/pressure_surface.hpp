// Rest area vectors for a pressure on the inside of a cylindrical wall (a tire's air cavity, a
// pressurised ring or tube), for Simulation::add_pressure_surface and the follower pressure of
// kernels/body_acceleration.hpp.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "engine/particle_fill.hpp"

namespace firn {

// The wall's inner surface, radius `radius` about the axis along z through `center` over
// |z - center_z| < half_length, is carried by the first particle layer behind it (radius <= r <
// radius + h, h the particle spacing): each such particle gets N dA with N = e_r (out of the
// cavity, into the wall) and dA the surface's area shared equally among them; every other particle
// gets zero. The radial vectors are centred (their sum made zero), so that the pressure's net force
// on the wall is zero, as a uniform pressure's on a whole cylinder is. Empty when no particle lies
// in the layer.
inline std::vector<Point> inner_cylinder_areas(const std::vector<Point>& positions, const Point& center, double radius,
                                               double half_length, double h) {
  std::vector<std::size_t> layer;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const double r = std::hypot(positions[i][0] - center[0], positions[i][1] - center[1]);
    if (r >= radius && r < radius + h && std::fabs(positions[i][2] - center[2]) < half_length) layer.push_back(i);
  }
  if (layer.empty()) return {};
  constexpr double kPi = 3.14159265358979323846;
  const double area = 2 * kPi * radius * 2 * half_length / double(layer.size());
  std::vector<Point> areas(positions.size(), Point{0, 0, 0});
  double mean[2] = {0, 0};
  for (std::size_t i : layer) {
    const double rx = positions[i][0] - center[0], ry = positions[i][1] - center[1], r = std::hypot(rx, ry);
    areas[i] = {area * rx / r, area * ry / r, 0};
    for (int d = 0; d < 2; ++d) mean[d] += areas[i][d] / double(layer.size());
  }
  for (std::size_t i : layer)
    for (int d = 0; d < 2; ++d) areas[i][d] -= mean[d];
  return areas;
}

}  // namespace firn
