// An 8-bit RGB image and the few drawing primitives firn's figures need on the CPU: filled
// rectangles, text in stb_easy_font's built-in bitmap font and copies (footprint maps here, the legend of
// rendered frames in viz/legend.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace firn {

using Rgb = std::array<float, 3>;  // sRGB components in [0, 1]

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3, rows top to bottom
  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(std::size_t(w) * std::size_t(h) * 3) {}
  std::uint8_t* pixel(int x, int y) { return &rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3]; }
};

// Fills the pixels x0 <= x < x1, y0 <= y < y1, clipped to the image.
void fill_rect(Image& image, int x0, int y0, int x1, int y1, Rgb color);

// Draws `text` with its top-left corner at (x, y) in pixels, each font pixel `scale` pixels wide;
// a line is 12 font pixels high.
void draw_text(Image& image, int x, int y, const std::string& text, Rgb color, int scale);

// The width of `text` in pixels at `scale`.
int text_width(const std::string& text, int scale);

// Copies `source` into `image` with its top-left corner at (x, y), clipped to the image.
void blit(Image& image, const Image& source, int x, int y);

}  // namespace firn
