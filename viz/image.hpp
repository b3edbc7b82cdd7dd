// An 8-bit RGB image, rows top to bottom.
#pragma once

#include <cstdint>
#include <vector>

namespace firn::viz {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3
  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(std::size_t(w) * std::size_t(h) * 3) {}
  std::uint8_t* pixel(int x, int y) { return &rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3]; }
};

}  // namespace firn::viz
