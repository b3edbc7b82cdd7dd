// The legend drawn onto a finished frame (on the CPU, after read-back): a colour bar with the
// field's name and range, or a swatch per material; and the simulated time. Text uses
// stb_easy_font's built-in bitmap font.
#pragma once

#include <string>
#include <vector>

#include "viz/color_map.hpp"
#include "viz/image.hpp"

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

// Draws `text` with its top-left corner at (x, y) in pixels, each font pixel `scale` pixels wide.
void draw_text(Image& image, int x, int y, const std::string& text, Rgb color, int scale);

// The width in pixels that draw_text gives `text` at `scale`.
int text_width(const std::string& text, int scale);

}  // namespace firn::viz
