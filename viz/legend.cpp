#include "viz/legend.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace firn::viz {
namespace {

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

const Rgb kInk = {0.12f, 0.12f, 0.14f};

// Lightens the pixels x0 <= x < x1, y0 <= y < y1 three quarters of the way to white, so dark text
// stays readable over a dark body (a tire) behind it.
void lighten(Image& image, int x0, int y0, int x1, int y1) {
  for (int y = std::max(y0, 0); y < std::min(y1, image.height); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, image.width); ++x)
      for (int k = 0; k < 3; ++k) image.pixel(x, y)[k] = std::uint8_t(255 - (255 - image.pixel(x, y)[k]) / 4);
}

}  // namespace

void draw_legend(Image& image, const Legend& legend) {
  const int scale = std::max(1, image.height / 360);
  const int margin = 8 * scale, line = 12 * scale;
  int x = image.width - margin - 150 * scale, y = margin;
  const int rows = legend.names.empty() ? 3 : 1 + int(legend.names.size());
  lighten(image, x - 4 * scale, y - 4 * scale, x + 150 * scale, y + rows * line + 2 * scale);
  if (!legend.caption.empty())
    lighten(image, margin - 4 * scale, image.height - margin - 12 * scale,
            margin + text_width(legend.caption, scale) + 4 * scale, image.height - margin + 2 * scale);
  draw_text(image, x, y, legend.title, kInk, scale);
  y += line;
  if (!legend.names.empty()) {
    for (std::size_t i = 0; i < legend.names.size(); ++i) {
      fill_rect(image, x, y, x + 9 * scale, y + 9 * scale, kInk);
      fill_rect(image, x + scale, y + scale, x + 8 * scale, y + 8 * scale, legend.colors[i]);
      draw_text(image, x + 13 * scale, y + scale, legend.names[i], kInk, scale);
      y += line;
    }
  } else {
    const int w = 120 * scale, h = 10 * scale;
    fill_rect(image, x - scale, y - scale, x + w + scale, y + h + scale, kInk);
    for (int i = 0; i < w; ++i)
      fill_rect(image, x + i, y, x + i + 1, y + h, color_map_rgb(legend.map, (i + 0.5) / w));
    y += h + 3 * scale;
    draw_text(image, x, y, number_text(legend.min), kInk, scale);
    const std::string hi = number_text(legend.max);
    draw_text(image, x + w - text_width(hi, scale), y, hi, kInk, scale);
  }
  if (!legend.caption.empty()) draw_text(image, margin, image.height - margin - 8 * scale, legend.caption, kInk, scale);
}

}  // namespace firn::viz
