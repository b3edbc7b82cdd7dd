#include "engine/output/footprint_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/output/atomic_file.hpp"
#include "engine/output/colour_map.hpp"
#include "engine/output/png_file.hpp"

namespace firn {

double write_footprint(const std::string& stem, const FootprintMap& map, const FootprintWindow& w) {
  auto column = [&](double x, double origin, int count) {
    return std::clamp(int(std::lround((x - origin) / map.dx)), 0, count - 1);
  };
  const int i0 = column(w.center_x - w.half_x, map.origin_x, map.nx), i1 = column(w.center_x + w.half_x, map.origin_x, map.nx);
  const int k0 = column(w.center_z - w.half_z, map.origin_z, map.nz), k1 = column(w.center_z + w.half_z, map.origin_z, map.nz);
  const int nx = i1 - i0 + 1, nz = k1 - k0 + 1;
  const double per_area = map.time > 0 ? 1 / (map.time * map.dx * map.dx) : 0;
  std::vector<double> p(std::size_t(nx) * std::size_t(nz));
  double peak = 0;
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      const double v = map.impulse[std::size_t(i0 + i) * std::size_t(map.nz) + std::size_t(k0 + k)] * per_area;
      p[std::size_t(k) * std::size_t(nx) + std::size_t(i)] = v;
      peak = std::max(peak, v);
    }

  std::string csv = "z\\x";
  char buf[32];
  for (int i = 0; i < nx; ++i) {
    std::snprintf(buf, sizeof buf, ",%.6g", map.origin_x + (i0 + i) * map.dx);
    csv += buf;
  }
  csv += '\n';
  for (int k = 0; k < nz; ++k) {
    std::snprintf(buf, sizeof buf, "%.6g", map.origin_z + (k0 + k) * map.dx);
    csv += buf;
    for (int i = 0; i < nx; ++i) {
      std::snprintf(buf, sizeof buf, ",%.6g", p[std::size_t(k) * std::size_t(nx) + std::size_t(i)]);
      csv += buf;
    }
    csv += '\n';
  }
  write_file_atomically(stem + ".csv", csv);

  constexpr int kScale = 6, kGap = 4, kBar = 10;
  const int width = nx * kScale + kGap + kBar, height = nz * kScale;
  std::vector<std::uint8_t> rgb(std::size_t(width) * std::size_t(height) * 3, 255);
  auto put = [&](int x, int y, const std::array<float, 3>& c) {
    for (int q = 0; q < 3; ++q)
      rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3 + std::size_t(q)] = std::uint8_t(std::lround(255 * c[q]));
  };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < nx * kScale; ++x) {
      const double v = p[std::size_t(y / kScale) * std::size_t(nx) + std::size_t(x / kScale)];
      put(x, y, viridis(peak > 0 ? v / peak : 0));
    }
    for (int x = nx * kScale + kGap; x < width; ++x) put(x, y, viridis(1 - double(y) / std::max(1, height - 1)));
  }
  write_png_rgb(stem + ".png", width, height, rgb.data());
  return peak;
}

}  // namespace firn
