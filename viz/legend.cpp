#include "viz/legend.hpp"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace firn::viz {
namespace {

void fill_rect(Image& image, int x0, int y0, int x1, int y1, Rgb color) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, image.width), y1 = std::min(y1, image.height);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int k = 0; k < 3; ++k) image.pixel(x, y)[k] = std::uint8_t(std::lround(255 * color[std::size_t(k)]));
}

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

const Rgb kInk = {0.12f, 0.12f, 0.14f};

}  // namespace

void draw_text(Image& image, int x, int y, const std::string& text, Rgb color, int scale) {
  // stb_easy_font: 4 vertices of 16 bytes (x, y, z floats, RGBA bytes) per quad.
  std::vector<char> buffer(text.size() * 270 * 4 + 1024);
  std::string copy = text;
  const int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size()));
  for (int q = 0; q < quads; ++q) {
    const float* v0 = reinterpret_cast<const float*>(&buffer[std::size_t(q) * 64]);
    const float* v2 = reinterpret_cast<const float*>(&buffer[std::size_t(q) * 64 + 32]);
    fill_rect(image, x + int(v0[0]) * scale, y + int(v0[1]) * scale, x + int(v2[0]) * scale, y + int(v2[1]) * scale,
              color);
  }
}

int text_width(const std::string& text, int scale) {
  std::string copy = text;
  return stb_easy_font_width(copy.data()) * scale;
}

void draw_legend(Image& image, const Legend& legend) {
  const int scale = std::max(1, image.height / 360);
  const int margin = 8 * scale, line = 12 * scale;
  int x = image.width - margin - 150 * scale, y = margin;
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
