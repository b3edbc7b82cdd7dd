// The Zhu and Bridson (2005) signed distance field around the particles, thesis Eq. 4.10-4.14:
//   phi(x) = |x - x_avg| - r_avg,                                  (4.10)
//   x_avg = sum_i w_i x_i,  r_avg = sum_i w_i r_i,                  (4.11, 4.12)
//   w_i = k(|x - x_i| / R) / sum_j k(|x - x_j| / R),                (4.13)
//   k(s) = max(0, (1 - s^2)^3),                                     (4.14)
// sampled on a sparse grid of spacing h whose nodes sit at integer multiples of h in world
// coordinates (so a translation by whole cells translates the samples exactly). The same weights
// average the particles' rest positions x0 into each node's material coordinates.
//
// Sparse layout: 8x8x8-node blocks over the particles' bounding box (plus one block of margin).
// Particles are binned by the block they lie in (a stable counting sort, so the order inside a bin
// is the particle order); a block is active when it or one of its 26 neighbours holds particles.
// Each active block gathers the particles of the 27 bins around it and accumulates their kernel
// weights into its own nodes only: no two threads write the same node, and every node sums its
// particles in the same order whatever the thread count, so the field is bitwise reproducible.
// Since R < 8h, a particle reaches only nodes of its own and neighbouring blocks, and nodes of
// inactive blocks have no particle within R: they are outside. The dense block map costs 9 bytes
// per 8^3 nodes of the particles' bounding box (at h = 1 mm, a 1 m box: 18 MB).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "kernels/backend/schedule.hpp"
#include "kernels/particle_attributes.hpp"
#include "viz/surface/surface_mesh.hpp"

namespace firn::surface {

constexpr int kBlockShift = 3;
constexpr int kBlockNodes = 1 << kBlockShift;  // nodes per block edge
constexpr int kBlockMask = kBlockNodes - 1;
constexpr int kNodesPerBlock = kBlockNodes * kBlockNodes * kBlockNodes;
constexpr double kMaxKernelRadius = kBlockNodes - 2;  // in units of h, see the header comment

// A node's index inside its block: x slowest, z fastest.
inline int local_node(int lx, int ly, int lz) { return (lx << (2 * kBlockShift)) | (ly << kBlockShift) | lz; }

struct FieldGrid {
  double h = 0;                 // node spacing (m)
  long origin[3] = {0, 0, 0};   // world node index of block (0,0,0)'s first node
  int blocks[3] = {0, 0, 0};    // extent of the dense block map
  float outside_value = 0;      // phi at nodes no particle reaches
  std::vector<std::int32_t> slot_of_block;  // dense block id -> active slot, or -1
  std::vector<std::uint32_t> active_blocks;  // block ids of the active blocks, increasing
  std::vector<float> phi;                    // kNodesPerBlock per active slot
  std::vector<Vec3f> rest;                   // material coordinates per node; NaN where no particle reaches

  std::size_t block_id(int bx, int by, int bz) const { return (std::size_t(bx) * blocks[1] + by) * blocks[2] + bz; }
  // Active slot of block (bx, by, bz), or -1 when it is inactive or off the map.
  int slot(int bx, int by, int bz) const {
    if (bx < 0 || by < 0 || bz < 0 || bx >= blocks[0] || by >= blocks[1] || bz >= blocks[2]) return -1;
    return slot_of_block[block_id(bx, by, bz)];
  }
  void block_coords(std::uint32_t id, int b[3]) const {
    b[0] = int(id / (std::uint32_t(blocks[1]) * blocks[2]));
    b[1] = int(id / blocks[2] % blocks[1]);
    b[2] = int(id % blocks[2]);
  }
};

namespace detail {

// The particles sorted by block, copied into contiguous columns for the gather.
template <class T>
struct BinnedParticles {
  std::vector<std::uint32_t> bin_begin;  // per dense block id, plus one
  std::vector<T> x[3], x0[3], radius;
};

template <class T>
struct Bounds {
  T lo[3] = {std::numeric_limits<T>::max(), std::numeric_limits<T>::max(), std::numeric_limits<T>::max()};
  T hi[3] = {std::numeric_limits<T>::lowest(), std::numeric_limits<T>::lowest(), std::numeric_limits<T>::lowest()};
};

template <class T, class Backend>
Bounds<T> particle_bounds(const ParticleView<T>& particles, const Backend& backend) {
  return backend.parallel_reduce(
      "surface_bounds", particles.n, Bounds<T>{},
      [&](std::size_t p, Bounds<T>& b) {
        for (int d = 0; d < 3; ++d) {
          b.lo[d] = std::fmin(b.lo[d], particles.x[d][p]);
          b.hi[d] = std::fmax(b.hi[d], particles.x[d][p]);
        }
      },
      [](Bounds<T>& a, const Bounds<T>& b) {
        for (int d = 0; d < 3; ++d) {
          a.lo[d] = std::fmin(a.lo[d], b.lo[d]);
          a.hi[d] = std::fmax(a.hi[d], b.hi[d]);
        }
      });
}

// Stable counting sort of the particles by block; the radius is r_i = particle_radius cbrt(vol0_i).
// Without rest positions (x0 not allocated) the current positions stand in for them.
template <class T, class Backend>
BinnedParticles<T> bin_particles(const ParticleView<T>& particles, const FieldGrid& grid, double particle_radius,
                                 const Backend& backend) {
  const std::size_t n = particles.n, block_count = grid.slot_of_block.size();
  std::vector<std::uint32_t> bin(n);
  backend.parallel_for("surface_bin_keys", n, [&](std::size_t p) {
    int b[3];  // the same arithmetic as the bounds in compute_scalar_field
    for (int d = 0; d < 3; ++d)
      b[d] = int((long(std::floor(double(particles.x[d][p]) / grid.h)) - grid.origin[d]) >> kBlockShift);
    bin[p] = std::uint32_t(grid.block_id(b[0], b[1], b[2]));
  });
  BinnedParticles<T> out;
  out.bin_begin.assign(block_count + 1, 0);
  for (std::size_t p = 0; p < n; ++p) ++out.bin_begin[bin[p] + 1];
  for (std::size_t b = 0; b < block_count; ++b) out.bin_begin[b + 1] += out.bin_begin[b];
  std::vector<std::uint32_t> order(n), next(out.bin_begin.begin(), out.bin_begin.end() - 1);
  for (std::size_t p = 0; p < n; ++p) order[next[bin[p]]++] = std::uint32_t(p);

  T* const* rest = particles.x0[0] ? particles.x0 : particles.x;
  for (int d = 0; d < 3; ++d) {
    out.x[d].resize(n);
    out.x0[d].resize(n);
  }
  out.radius.resize(n);
  backend.parallel_for("surface_bin_gather", n, [&](std::size_t j) {
    const std::uint32_t p = order[j];
    for (int d = 0; d < 3; ++d) {
      out.x[d][j] = particles.x[d][p];
      out.x0[d][j] = rest[d][p];
    }
    out.radius[j] = T(particle_radius) * std::cbrt(particles.vol0[p]);
  });
  return out;
}

}  // namespace detail

// The largest rest spacing cbrt(vol0) of the particles (m).
template <class T, class Backend>
double largest_particle_spacing(const ParticleView<T>& particles, const Backend& backend) {
  const T largest_volume = backend.parallel_reduce(
      "surface_largest_volume", particles.n, T(0), [&](std::size_t p, T& v) { v = std::max(v, particles.vol0[p]); },
      [](T& a, const T& b) { a = std::max(a, b); });
  return std::cbrt(double(largest_volume));
}

// Samples phi and the material coordinates on the sparse grid. h and R in metres.
template <class T, class Backend>
FieldGrid compute_scalar_field(const ParticleView<T>& particles, double h, double kernel_radius,
                               double particle_radius, const Backend& backend) {
  if (!(h > 0)) throw std::invalid_argument("surface: the sampling spacing must be positive");
  if (!(kernel_radius > 0 && kernel_radius <= kMaxKernelRadius * h))
    throw std::invalid_argument("surface: the kernel radius must lie in (0, 6h]");
  FieldGrid grid;
  grid.h = h;
  grid.outside_value = float(kernel_radius);
  if (particles.n == 0) return grid;

  const detail::Bounds<T> bounds = detail::particle_bounds(particles, backend);
  for (int d = 0; d < 3; ++d)
    if (!std::isfinite(bounds.lo[d]) || !std::isfinite(bounds.hi[d]))
      throw std::invalid_argument("surface: a particle position is not finite");
  for (int d = 0; d < 3; ++d) {
    // One block of margin on each side: particle bins lie in [1, blocks - 2], active blocks in
    // [0, blocks - 1].
    grid.origin[d] = long(std::floor(double(bounds.lo[d]) / h)) - kBlockNodes;
    grid.blocks[d] = int((long(std::floor(double(bounds.hi[d]) / h)) - grid.origin[d]) >> kBlockShift) + 2;
  }
  const std::size_t block_count = std::size_t(grid.blocks[0]) * grid.blocks[1] * grid.blocks[2];
  grid.slot_of_block.assign(block_count, -1);
  const detail::BinnedParticles<T> bins = detail::bin_particles(particles, grid, particle_radius, backend);

  std::vector<std::uint8_t> active(block_count, 0);
  for (int bx = 1; bx + 1 < grid.blocks[0]; ++bx)
    for (int by = 1; by + 1 < grid.blocks[1]; ++by)
      for (int bz = 1; bz + 1 < grid.blocks[2]; ++bz) {
        const std::size_t id = grid.block_id(bx, by, bz);
        if (bins.bin_begin[id] == bins.bin_begin[id + 1]) continue;
        for (int o = 0; o < 27; ++o) active[grid.block_id(bx + o / 9 - 1, by + o / 3 % 3 - 1, bz + o % 3 - 1)] = 1;
      }
  for (std::size_t id = 0; id < block_count; ++id)
    if (active[id]) {
      grid.slot_of_block[id] = std::int32_t(grid.active_blocks.size());
      grid.active_blocks.push_back(std::uint32_t(id));
    }
  grid.phi.resize(grid.active_blocks.size() * kNodesPerBlock);
  grid.rest.resize(grid.active_blocks.size() * kNodesPerBlock);

  const T th = T(h), R = T(kernel_radius), inv_R2 = T(1 / (kernel_radius * kernel_radius));
  backend.parallel_for(
      "surface_field", grid.active_blocks.size(),
      [&](std::size_t slot) {
        int b[3];
        grid.block_coords(grid.active_blocks[slot], b);
        long first[3];  // world index of the block's first node
        for (int d = 0; d < 3; ++d) first[d] = grid.origin[d] + (long(b[d]) << kBlockShift);
        // Kernel-weighted sums per node: sum k, sum k (x_i - x), sum k r_i, sum k x0_i.
        T weight[kNodesPerBlock] = {}, offset[3][kNodesPerBlock] = {}, radius[kNodesPerBlock] = {},
          rest[3][kNodesPerBlock] = {};
        for (int o = 0; o < 27; ++o) {
          const int nb[3] = {b[0] + o / 9 - 1, b[1] + o / 3 % 3 - 1, b[2] + o % 3 - 1};
          if (nb[0] < 0 || nb[1] < 0 || nb[2] < 0 || nb[0] >= grid.blocks[0] || nb[1] >= grid.blocks[1] ||
              nb[2] >= grid.blocks[2])
            continue;
          const std::size_t bin = grid.block_id(nb[0], nb[1], nb[2]);
          for (std::uint32_t j = bins.bin_begin[bin]; j < bins.bin_begin[bin + 1]; ++j) {
            const T p[3] = {bins.x[0][j], bins.x[1][j], bins.x[2][j]};
            int lo[3], hi[3];
            bool reaches = true;
            for (int d = 0; d < 3; ++d) {
              lo[d] = int(std::max(long(std::ceil((p[d] - R) / th)) - first[d], 0L));
              hi[d] = int(std::min(long(std::floor((p[d] + R) / th)) - first[d], long(kBlockMask)));
              reaches = reaches && lo[d] <= hi[d];
            }
            if (!reaches) continue;
            for (int ix = lo[0]; ix <= hi[0]; ++ix) {
              const T dx = p[0] - T(first[0] + ix) * th;
              for (int iy = lo[1]; iy <= hi[1]; ++iy) {
                const T dy = p[1] - T(first[1] + iy) * th;
                for (int iz = lo[2]; iz <= hi[2]; ++iz) {
                  const T dz = p[2] - T(first[2] + iz) * th;
                  const T s2 = (dx * dx + dy * dy + dz * dz) * inv_R2;
                  if (s2 >= T(1)) continue;
                  const T t = T(1) - s2, k = t * t * t;  // Eq. 4.14
                  const int node = local_node(ix, iy, iz);
                  weight[node] += k;
                  offset[0][node] += k * dx;
                  offset[1][node] += k * dy;
                  offset[2][node] += k * dz;
                  radius[node] += k * bins.radius[j];
                  rest[0][node] += k * bins.x0[0][j];
                  rest[1][node] += k * bins.x0[1][j];
                  rest[2][node] += k * bins.x0[2][j];
                }
              }
            }
          }
        }
        float* phi = &grid.phi[slot * kNodesPerBlock];
        Vec3f* material = &grid.rest[slot * kNodesPerBlock];
        for (int node = 0; node < kNodesPerBlock; ++node) {
          if (weight[node] > T(0)) {
            const T inv = T(1) / weight[node];
            // Eq. 4.10 with x_avg - x = sum k (x_i - x) / sum k (Eq. 4.11, 4.13).
            const T ox = offset[0][node] * inv, oy = offset[1][node] * inv, oz = offset[2][node] * inv;
            phi[node] = float(std::sqrt(ox * ox + oy * oy + oz * oz) - radius[node] * inv);
            material[node] = {{float(rest[0][node] * inv), float(rest[1][node] * inv), float(rest[2][node] * inv)}};
          } else {
            phi[node] = grid.outside_value;
            const float nan = std::numeric_limits<float>::quiet_NaN();
            material[node] = {{nan, nan, nan}};
          }
        }
      },
      backend::Schedule::uneven);
  return grid;
}

}  // namespace firn::surface
