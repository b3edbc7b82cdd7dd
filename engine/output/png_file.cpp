#include "engine/output/png_file.hpp"

#include <zlib.h>

#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include "engine/output/atomic_file.hpp"

namespace {

// stb's hook for its deflate step: returns a malloc'ed buffer of zlib-format data.
unsigned char* zlib_level1(unsigned char* data, int size, int* out_size, int /*stb's quality*/) {
  uLongf bound = compressBound(uLong(size));
  auto* out = static_cast<unsigned char*>(std::malloc(bound));
  if (!out || compress2(out, &bound, data, uLong(size), 1) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *out_size = int(bound);
  return out;
}

}  // namespace

#define STBIW_ZLIB_COMPRESS zlib_level1
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

namespace firn {

void write_png_rgb(const std::string& path, int width, int height, const std::uint8_t* rgb) {
  std::string bytes;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
  };
  if (!stbi_write_png_to_func(append, &bytes, width, height, 3, rgb, width * 3))
    throw std::runtime_error("cannot encode " + path);
  write_file_atomically(path, bytes);
}

}  // namespace firn
