// A rubber tire's tread stress (issue 17 item 5; the thesis' Figure 5.7, the stress distribution
// over each tread's footprint): the von Mises stress of the tread's particles under the axle, per
// grid column (x, z) about the axle, written and drawn like the footprint
// (engine/output/footprint_writer.hpp, write_map).
#pragma once

#include <cstddef>
#include <vector>

#include "engine/output/footprint_figure.hpp"
#include "engine/particle_fields.hpp"
#include "kernels/colliders.hpp"

namespace firn {

// How its figure names the loaded columns and the empty ones (FootprintFigureSpec patch, empty).
inline constexpr const char* kTreadStressPatch = "stressed tread";
inline constexpr const char* kTreadStressEmpty = "no tread below the axle";

// The tread's particles: those of [begin, end) farther than `inner` from the axle through `tire`'s
// centre (along its z axis) and below it. Each column of the window (x within radius, z within
// half_z of the axle, columns dx wide) holds the mean von Mises stress of those in it (Pa).
template <class T>
FootprintField tread_stress_field(const ParticleView<T>& pv, std::size_t begin, std::size_t end,
                                  const Collider<double>& tire, double inner, double half_z, double dx) {
  FootprintField f;
  const double r = tire.tire.radius;
  f.dx = dx;
  f.nx = int(2 * r / dx) + 1, f.nz = int(2 * half_z / dx) + 1;
  f.x0 = tire.center[0] - 0.5 * (f.nx - 1) * dx, f.z0 = tire.center[2] - 0.5 * (f.nz - 1) * dx;
  f.pressure.assign(std::size_t(f.nx) * std::size_t(f.nz), 0.0);
  std::vector<int> count(f.pressure.size(), 0);
  for (std::size_t p = begin; p < end; ++p) {
    const double x = double(pv.x[0][p]), y = double(pv.x[1][p]), z = double(pv.x[2][p]);
    const double rx = x - tire.center[0], ry = y - tire.center[1];
    if (ry >= 0 || rx * rx + ry * ry < inner * inner) continue;
    const int i = int(std::lround((x - f.x0) / dx)), k = int(std::lround((z - f.z0) / dx));
    if (i < 0 || i >= f.nx || k < 0 || k >= f.nz) continue;
    const std::size_t c = std::size_t(k) * std::size_t(f.nx) + std::size_t(i);
    f.pressure[c] += double(particle_von_mises(pv, p));
    ++count[c];
  }
  for (std::size_t c = 0; c < f.pressure.size(); ++c)
    if (count[c] > 0) f.pressure[c] /= count[c];
  return f;
}

}  // namespace firn
