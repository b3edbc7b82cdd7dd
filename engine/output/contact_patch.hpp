// The length of a rubber body's contact patch on a plane (issue 17 item 6: the inflated tire's
// patch against the classic estimate load / (pressure x width)), measured on the rubber's particles.
//
// A particle stands for a cube of side h (the particle spacing) about its position, so it touches
// the plane when that cube reaches it: its signed distance to the plane is at most h / 2. The patch
// runs along x from the first touching particle's cube to the last one's, so its length is their
// extent along x plus h. It is known to a lattice row: the tread's lowest particles form a staircase
// of the lattice's rows, and the reading steps by one row's extent at each end (8-16 mm for 2.67 mm
// particles on a 0.2 m tire deflected by 4-7 mm; README, "Inflation"). And it depends on where the
// grid contact holds the body: through the nodes a cell inside the plane, so a lightly pressed
// body can sit above h / 2 and read nothing (an inflated band 20 mm wide, pressed with 340 N at
// dx = 8 mm with 2.67 mm particles, sat 1.6-1.9 mm up and read 0), and a heavily pressed one sinks
// below the plane (an inflated tire's bottom row, 1.1-1.8 mm).
//
// Why not the road's load: the grid contact carries a particle's load through the nodes a cell
// inside the road, with a B-spline weight that falls with the particle's height above it, so the
// road's line load peaks where the rubber has sunk deepest and tails off over a cell past where it
// touches. Where that load falls to half its plateau was this metric before: at dx = 8 mm it read
// 81-89 mm for an inflated tire whose tread touches the road over 124-140 mm, and 64 mm at dx = 4 mm
// where the tread touches over 120 mm (README, "Inflation").
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>

#include "kernels/colliders.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn {

// The patch length along x of the particles [begin, end) on `plane` (0 when none touches it).
template <class T>
double contact_patch_length(const ParticleView<T>& pv, std::size_t begin, std::size_t end,
                            const Collider<double>& plane, double spacing) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t p = begin; p < end; ++p) {
    const double x[3] = {double(pv.x[0][p]), double(pv.x[1][p]), double(pv.x[2][p])};
    double n[3];
    if (plane.distance(x, n) > 0.5 * spacing) continue;
    lo = std::min(lo, x[0]);
    hi = std::max(hi, x[0]);
  }
  return hi >= lo ? hi - lo + spacing : 0.0;
}

}  // namespace firn
