#include "engine/fragments.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace firn {
namespace {

struct UnionFind {
  std::vector<std::size_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t(0)); }
  std::size_t find(std::size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void join(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// A cell's integer coordinates packed into one key (21 bits each, offset so negatives fit).
std::uint64_t cell_key(std::int64_t i, std::int64_t j, std::int64_t k) {
  constexpr std::int64_t kOffset = std::int64_t(1) << 20, kMask = (std::int64_t(1) << 21) - 1;
  return (std::uint64_t((i + kOffset) & kMask) << 42) | (std::uint64_t((j + kOffset) & kMask) << 21) |
         std::uint64_t((k + kOffset) & kMask);
}

}  // namespace

FragmentCount count_fragments(const std::vector<std::array<double, 3>>& x, double link, std::size_t min_particles) {
  const std::size_t n = x.size();
  std::vector<std::array<std::int64_t, 3>> cell(n);
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> members;
  members.reserve(n);
  for (std::size_t p = 0; p < n; ++p) {
    for (int d = 0; d < 3; ++d) cell[p][d] = std::int64_t(std::floor(x[p][d] / link));
    members[cell_key(cell[p][0], cell[p][1], cell[p][2])].push_back(p);
  }
  UnionFind sets(n);
  const double link2 = link * link;
  for (std::size_t p = 0; p < n; ++p)
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int c = -1; c <= 1; ++c) {
          const auto it = members.find(cell_key(cell[p][0] + a, cell[p][1] + b, cell[p][2] + c));
          if (it == members.end()) continue;
          for (std::size_t q : it->second) {
            if (q <= p) continue;
            double r2 = 0;
            for (int d = 0; d < 3; ++d) r2 += (x[p][d] - x[q][d]) * (x[p][d] - x[q][d]);
            if (r2 < link2) sets.join(p, q);
          }
        }
  std::vector<std::size_t> size(n, 0);
  for (std::size_t p = 0; p < n; ++p) ++size[sets.find(p)];
  FragmentCount count;
  for (std::size_t s : size) {
    count.fragments += s >= min_particles;  // min_particles >= 1: non-roots (0) never count
    count.largest = std::max(count.largest, s);
  }
  return count;
}

}  // namespace firn
