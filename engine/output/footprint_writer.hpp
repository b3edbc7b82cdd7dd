// The tire's footprint: the contact pressure under it, per grid column, averaged over a frame
// (issue 5, "Metrics"; the thesis' Figure 5.7). Written as a CSV grid and a figure
// (engine/output/footprint_figure.hpp).
#pragma once

#include <optional>
#include <string>

#include "engine/output/footprint_figure.hpp"
#include "engine/simulation.hpp"

namespace firn {

// The window of grid columns shown: x within `half_x` and z within `half_z` of (x, z) = centre.
struct FootprintWindow {
  double center_x, center_z, half_x, half_z;
};

// The window's columns of `map` as pressures (Pa).
FootprintField footprint_field(const FootprintMap& map, const FootprintWindow& window);

// Which part of `tire` (a tire collider at its current pose) lies over a ground point: a point
// half a tread depth inside its outer radius, straight above, decides block or groove.
TreadCoverAt tread_cover(const Collider<double>& tire);

// Writes STEM.csv (first row "z\x" and the column positions in m, then one row per z: its
// position, then the values in Pa) and STEM.png (the figure of `spec`). Returns the peak.
double write_map(const std::string& stem, const FootprintField& field, const FootprintFigureSpec& spec);

// The footprint's map of `window`, with the tire's tread outline and `title`; returns its peak.
double write_footprint(const std::string& stem, const FootprintMap& map, const FootprintWindow& window,
                       const Collider<double>& tire, const std::string& title);

// A STEM.csv written above, read back; none when it cannot be read or is not such a grid.
std::optional<FootprintField> read_footprint_csv(const std::string& path);

}  // namespace firn
