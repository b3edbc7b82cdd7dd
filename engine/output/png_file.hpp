// PNG files through stb_image_write (Debian's libstb-dev), deflated by zlib at level 1 in place of
// stb's own compressor (STBIW_ZLIB_COMPRESS; DESIGN.md section 7: several times faster, files a
// little larger). The one PNG encoder of firn: footprint maps and rendered frames; and the decoder
// (stb_image) that reads frames back for a sweep's contact sheets.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/output/image.hpp"

namespace firn {

// `height` rows of `width` RGB pixels (8 bits each, top row first), encoded.
std::vector<unsigned char> encode_png_rgb(int width, int height, const std::uint8_t* rgb);

// The same, written atomically to `path`; throws std::runtime_error on failure.
void write_png_rgb(const std::string& path, int width, int height, const std::uint8_t* rgb);

inline std::vector<unsigned char> encode_png(const Image& image) {
  return encode_png_rgb(image.width, image.height, image.rgb.data());
}

inline void write_png(const std::string& path, const Image& image) {
  write_png_rgb(path, image.width, image.height, image.rgb.data());
}

// A PNG file's pixels as 8-bit RGB (grey and alpha converted); throws std::runtime_error when the
// file cannot be read or decoded.
Image read_png_rgb(const std::string& path);

}  // namespace firn
