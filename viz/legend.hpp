// The legend drawn onto a finished frame (on the CPU, after read-back): a colour bar with the
// field's name and range, or a swatch per material; and the simulated time.
#pragma once

#include <string>
#include <vector>

#include "engine/output/image.hpp"
#include "viz/color_map.hpp"

namespace firn::viz {

struct Legend {
  std::string title;  // the field, e.g. "speed (m/s)"; or "material"
  // Colour bar: map and range. Swatches: one per entry (name, colour) when `names` is not empty.
  ColorMap map = ColorMap::viridis;
  double min = 0, max = 1;
  std::vector<std::string> names;
  std::vector<Rgb> colors;
  std::string caption;  // e.g. "t = 2.500 ms", bottom left
};

void draw_legend(Image& image, const Legend& legend);

}  // namespace firn::viz
