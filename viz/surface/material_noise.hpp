// Hash-based value noise evaluated at material (rest) coordinates, so that a piece of snow keeps
// its grains wherever it moves. Pure functions of (point, seed): no tables, no state, identical on
// every thread and in every frame.
#pragma once

#include <cmath>
#include <cstdint>

#include "kernels/mat3.hpp"

namespace firn::surface {

// An integer finaliser with good avalanche (the "lowbias32" multiply-xorshift constants found by
// C. Wellons' hash-prospector search).
inline std::uint32_t mix_bits(std::uint32_t h) {
  h ^= h >> 16;
  h *= 0x7feb352dU;
  h ^= h >> 15;
  h *= 0x846ca68bU;
  h ^= h >> 16;
  return h;
}

inline std::uint32_t lattice_hash(std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t seed) {
  std::uint32_t h = mix_bits(seed ^ std::uint32_t(x));
  h = mix_bits(h ^ std::uint32_t(y));
  return mix_bits(h ^ std::uint32_t(z));
}

// A uniform number in [0, 1) from the top 24 bits of a hash.
inline float unit_interval(std::uint32_t h) { return float(h >> 8) * (1.0f / 16777216.0f); }

// Value noise in [-1, 1] with unit lattice spacing: random values at the integer lattice blended by
// the quintic fade 6t^5 - 15t^4 + 10t^3 (C2-continuous, Perlin 2002).
inline float value_noise(const Vec3<float>& p, std::uint32_t seed) {
  std::int32_t cell[3];
  float fade[3];
  for (int d = 0; d < 3; ++d) {
    const float floor_d = std::floor(p[d]);
    cell[d] = std::int32_t(floor_d);
    const float t = p[d] - floor_d;
    fade[d] = t * t * t * (t * (t * 6 - 15) + 10);
  }
  float result = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const int ox = corner & 1, oy = corner >> 1 & 1, oz = corner >> 2 & 1;
    const float weight = (ox ? fade[0] : 1 - fade[0]) * (oy ? fade[1] : 1 - fade[1]) * (oz ? fade[2] : 1 - fade[2]);
    result += weight * (2 * unit_interval(lattice_hash(cell[0] + ox, cell[1] + oy, cell[2] + oz, seed)) - 1);
  }
  return result;
}

// Sum of `octaves` value-noise octaves, each of half the wavelength and half the amplitude of the
// one before, normalised to [-1, 1]. `p` is in units of the first octave's wavelength.
inline float fractal_noise(const Vec3<float>& p, int octaves, std::uint32_t seed) {
  float sum = 0, amplitude = 1, total = 0, scale = 1;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * value_noise(scale * p, seed + std::uint32_t(o));
    total += amplitude;
    amplitude *= 0.5f;
    scale *= 2;
  }
  return total > 0 ? sum / total : 0;
}

}  // namespace firn::surface
