// PNG encoding through stb_image_write with zlib's deflate at level 1 in place of stb's own
// compressor (STBIW_ZLIB_COMPRESS; DESIGN.md section 7: several times faster, files a little larger).
#pragma once

#include <string>
#include <vector>

#include "viz/image.hpp"

namespace firn::viz {

std::vector<unsigned char> encode_png(const Image& image);

// Writes the PNG atomically (a temporary name renamed when complete); throws on failure.
void write_png(const std::string& path, const Image& image);

}  // namespace firn::viz
