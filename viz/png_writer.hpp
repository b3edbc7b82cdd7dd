// Rendered images to PNG, through the engine's one PNG encoder (engine/output/png_file.hpp: stb
// with zlib's deflate at level 1).
#pragma once

#include <string>
#include <vector>

#include "engine/output/png_file.hpp"
#include "viz/image.hpp"

namespace firn::viz {

inline std::vector<unsigned char> encode_png(const Image& image) {
  return encode_png_rgb(image.width, image.height, image.rgb.data());
}

// Writes the PNG atomically (a temporary name renamed when complete); throws on failure.
inline void write_png(const std::string& path, const Image& image) {
  write_png_rgb(path, image.width, image.height, image.rgb.data());
}

}  // namespace firn::viz
