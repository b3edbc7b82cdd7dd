#include "studies/stability/stability_checkerboard.hpp"

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace firn::study {
namespace {

// Cell (i, j, k) of edge dx packed into one key; 21 bits per axis cover +-1e6 cells.
std::int64_t cell_key(long i, long j, long k) {
  const auto bits = [](long v) { return std::int64_t(v + (1L << 20)) & ((std::int64_t(1) << 21) - 1); };
  return (bits(i) << 42) | (bits(j) << 21) | bits(k);
}

}  // namespace

CheckerboardMeasure pressure_checkerboard(const PressureField& field, double dx) {
  CheckerboardMeasure m;
  const std::size_t n = field.pressures.size();
  if (n < 2) return m;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells;
  auto cell_of = [&](std::size_t p, int d) { return long(std::floor(field.positions[p][d] / dx)); };
  for (std::size_t p = 0; p < n; ++p) cells[cell_key(cell_of(p, 0), cell_of(p, 1), cell_of(p, 2))].push_back(p);
  double sum = 0, sum_sq = 0;
  std::size_t counted = 0;
  for (std::size_t p = 0; p < n; ++p) {
    sum += field.pressures[p];
    double nbr = 0;
    std::size_t count = 0;
    for (long di = -1; di <= 1; ++di)
      for (long dj = -1; dj <= 1; ++dj)
        for (long dk = -1; dk <= 1; ++dk) {
          const auto it = cells.find(cell_key(cell_of(p, 0) + di, cell_of(p, 1) + dj, cell_of(p, 2) + dk));
          if (it == cells.end()) continue;
          for (std::size_t q : it->second) {
            if (q == p) continue;
            double r2 = 0;
            for (int d = 0; d < 3; ++d) r2 += std::pow(field.positions[q][d] - field.positions[p][d], 2);
            if (r2 > dx * dx) continue;
            nbr += field.pressures[q];
            ++count;
          }
        }
    if (count == 0) continue;  // an isolated particle has no neighbourhood to compare with
    sum_sq += std::pow(field.pressures[p] - nbr / double(count), 2);
    ++counted;
  }
  m.mean_pressure = sum / double(n);
  if (counted > 0 && m.mean_pressure != 0) m.indicator = std::sqrt(sum_sq / double(counted)) / std::abs(m.mean_pressure);
  return m;
}

}  // namespace firn::study
