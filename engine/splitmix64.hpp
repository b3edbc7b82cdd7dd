// SplitMix64 (Steele, Lea and Flood 2014, "Fast splittable pseudorandom number generators",
// OOPSLA): a portable, seedable stream of 64-bit values, and its output mix alone as an integer
// hash. Scenes use it wherever they draw random numbers, so that a seeded scene is the same on
// every platform (std::uniform_real_distribution is implementation-defined).
#pragma once

#include <cstdint>

namespace firn {

// The generator's finaliser: a bijective mix of 64 bits (a good hash of an integer key).
inline std::uint64_t splitmix64_mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() { return splitmix64_mix(state += 0x9e3779b97f4a7c15ull); }
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)
};

}  // namespace firn
