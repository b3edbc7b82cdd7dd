#include "engine/output/image.hpp"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cmath>

namespace firn {

void fill_rect(Image& image, int x0, int y0, int x1, int y1, Rgb color) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, image.width), y1 = std::min(y1, image.height);
  std::uint8_t c[3];
  for (int k = 0; k < 3; ++k) c[k] = std::uint8_t(std::lround(255 * std::clamp(color[std::size_t(k)], 0.0f, 1.0f)));
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) std::copy(c, c + 3, image.pixel(x, y));
}

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

void blit(Image& image, const Image& source, int x, int y) {
  for (int row = std::max(0, -y); row < source.height && y + row < image.height; ++row) {
    const int from = std::max(0, -x), to = std::min(source.width, image.width - x);
    if (to > from)
      std::copy(source.rgb.begin() + (std::ptrdiff_t(row) * source.width + from) * 3,
                source.rgb.begin() + (std::ptrdiff_t(row) * source.width + to) * 3, image.pixel(x + from, y + row));
  }
}

}  // namespace firn
