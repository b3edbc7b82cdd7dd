// PNG files through stb_image_write (Debian's libstb-dev), compressed with zlib at level 1
// (STBIW_ZLIB_COMPRESS): 3-4x faster than stb's own deflate at a similar size (DESIGN.md
// section 7). Written atomically like every output file.
#pragma once

#include <cstdint>
#include <string>

namespace firn {

// Writes `height` rows of `width` RGB pixels (8 bits each, top row first) to `path`.
void write_png_rgb(const std::string& path, int width, int height, const std::uint8_t* rgb);

}  // namespace firn
