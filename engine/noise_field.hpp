// A smooth, seeded, deterministic noise field n(x) in [-1, 1] with correlation length `scale`,
// for materials whose parameters vary in space (engine/scene/material_variation.hpp).
//
// Lattice value noise (Lagae et al. 2010, "A Survey of Procedural Noise Functions", Computer
// Graphics Forum 29(8), on lattice noises): every node of a cubic lattice of spacing `scale` carries a
// pseudo-random value uniform in [-1, 1), hashed from its integer coordinates and the seed
// (SplitMix64's mix, engine/splitmix64.hpp), and n is the tensor-product interpolation of the 8
// nodes around x with Perlin's quintic fade 6t^5 - 15t^4 + 10t^3 (Perlin 2002, "Improving Noise",
// SIGGRAPH), so n is C2. Each n(x) is a convex combination of node values: it lies in [-1, 1].
// Value noise rather than gradient noise, whose value is 0 at every lattice node: a material
// should not be nominal on a regular lattice of points.
//
// Points much closer than `scale` take nearly the same value; points 2 `scale` or more apart
// along an axis share no lattice node and are independent. The mean is 0; the standard deviation
// is about 0.4 (tests/test_noise_field.cpp).
// Evaluated on the host in double precision, the same on every machine and thread count.
#pragma once

#include <array>
#include <cstdint>

namespace firn {

class NoiseField {
 public:
  NoiseField(double scale, std::uint64_t seed);
  double operator()(const std::array<double, 3>& x) const;
  double scale() const { return scale_; }

 private:
  double node(std::int64_t i, std::int64_t j, std::int64_t k) const;  // in [-1, 1)
  double scale_;
  std::uint64_t seed_;
};

}  // namespace firn
