// The tire's footprint: the contact pressure under it, per grid column, averaged over a frame
// (issue 5, "Metrics"; the thesis' Figure 5.7). Written as a CSV grid and a PNG heat map.
#pragma once

#include <string>

#include "engine/simulation.hpp"

namespace firn {

// The window of grid columns shown: x within `half_x` and z within `half_z` of (x, z) = centre.
struct FootprintWindow {
  double center_x, center_z, half_x, half_z;
};

// Writes STEM.csv (first row "z\x" and the column positions in m, then one row per z: its
// position, then the pressures in Pa) and STEM.png (x to the right, z downward, viridis from 0 to
// the window's peak, 6 pixels per column, a colour bar on the right). Returns the peak pressure.
double write_footprint(const std::string& stem, const FootprintMap& map, const FootprintWindow& window);

}  // namespace firn
