#include "engine/output/footprint_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "engine/output/atomic_file.hpp"
#include "engine/output/png_file.hpp"

namespace firn {

FootprintField footprint_field(const FootprintMap& map, const FootprintWindow& w) {
  auto column = [&](double x, double origin, int count) {
    return std::clamp(int(std::lround((x - origin) / map.dx)), 0, count - 1);
  };
  const int i0 = column(w.center_x - w.half_x, map.origin_x, map.nx), i1 = column(w.center_x + w.half_x, map.origin_x, map.nx);
  const int k0 = column(w.center_z - w.half_z, map.origin_z, map.nz), k1 = column(w.center_z + w.half_z, map.origin_z, map.nz);
  FootprintField f;
  f.nx = i1 - i0 + 1, f.nz = k1 - k0 + 1, f.dx = map.dx;
  f.x0 = map.origin_x + i0 * map.dx, f.z0 = map.origin_z + k0 * map.dx;
  const double per_area = map.time > 0 ? 1 / (map.time * map.dx * map.dx) : 0;
  f.pressure.resize(std::size_t(f.nx) * std::size_t(f.nz));
  for (int k = 0; k < f.nz; ++k)
    for (int i = 0; i < f.nx; ++i)
      f.pressure[std::size_t(k) * std::size_t(f.nx) + std::size_t(i)] =
          map.impulse[std::size_t(i0 + i) * std::size_t(map.nz) + std::size_t(k0 + k)] * per_area;
  return f;
}

TreadCoverAt tread_cover(const Collider<double>& tire) {
  return [tire](double x, double z) {
    const double r = tire.tire.radius, depth = tire.tire.tread_depth;
    const double u = x - tire.center[0];
    // The tire's axis is z (tire_shape.hpp); its lateral extent is about the centre.
    if (std::fabs(u) >= r || std::fabs(z - tire.center[2]) > 0.5 * tire.tire.width) return TreadCover::none;
    const double s = (r - 0.5 * depth) / r;
    const double p[3] = {tire.center[0] + s * u, tire.center[1] - s * std::sqrt(r * r - u * u), z};
    double n[3];
    return tire.distance(p, n) < 0 ? TreadCover::block : TreadCover::groove;
  };
}

double write_map(const std::string& stem, const FootprintField& f, const FootprintFigureSpec& spec) {
  std::string csv = "z\\x";
  char buf[32];
  for (int i = 0; i < f.nx; ++i) {
    std::snprintf(buf, sizeof buf, ",%.6g", f.x0 + i * f.dx);
    csv += buf;
  }
  csv += '\n';
  for (int k = 0; k < f.nz; ++k) {
    std::snprintf(buf, sizeof buf, "%.6g", f.z0 + k * f.dx);
    csv += buf;
    for (int i = 0; i < f.nx; ++i) {
      std::snprintf(buf, sizeof buf, ",%.6g", f.at(i, k));
      csv += buf;
    }
    csv += '\n';
  }
  write_file_atomically(stem + ".csv", csv);
  write_png(stem + ".png", draw_footprint_figure(f, spec));
  return footprint_stats(f).peak;
}

double write_footprint(const std::string& stem, const FootprintMap& map, const FootprintWindow& w,
                       const Collider<double>& tire, const std::string& title) {
  FootprintFigureSpec spec;
  spec.axle_x = w.center_x, spec.axle_z = w.center_z;
  spec.title = title;
  spec.tread = tread_cover(tire);
  return write_map(stem, footprint_field(map, w), spec);
}

std::optional<FootprintField> read_footprint_csv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  // One row of numbers after its first cell (the header's "z\x", or a row's z); none if a cell is
  // not a number.
  auto numbers = [](const std::string& row, double* first) -> std::optional<std::vector<double>> {
    std::vector<double> v;
    std::stringstream cells(row);
    std::string cell;
    for (bool head = true; std::getline(cells, cell, ','); head = false) {
      char* end = nullptr;
      const double x = std::strtod(cell.c_str(), &end);
      const bool number = !cell.empty() && end == cell.c_str() + cell.size();
      if (head) {
        if (first && !number) return std::nullopt;
        if (first) *first = x;
      } else {
        if (!number) return std::nullopt;
        v.push_back(x);
      }
    }
    return v;
  };
  if (!std::getline(in, line) || line.rfind("z\\x,", 0) != 0) return std::nullopt;
  const auto xs = numbers(line, nullptr);
  if (!xs || xs->size() < 2) return std::nullopt;
  FootprintField f;
  f.nx = int(xs->size()), f.x0 = xs->front(), f.dx = ((*xs)[1] - (*xs)[0]);
  std::vector<double> zs;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    double z = 0;
    const auto row = numbers(line, &z);
    if (!row || int(row->size()) != f.nx) return std::nullopt;
    zs.push_back(z);
    f.pressure.insert(f.pressure.end(), row->begin(), row->end());
  }
  if (zs.empty() || !(f.dx > 0)) return std::nullopt;
  f.nz = int(zs.size()), f.z0 = zs.front();
  return f;
}

}  // namespace firn
