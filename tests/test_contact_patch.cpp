// The contact patch length of a rubber body on a plane (engine/output/contact_patch.hpp): which
// particles touch (their cube of side h reaches the plane), the length from the first touching
// cube to the last, the particle range and a raised plane.
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "engine/output/contact_patch.hpp"

namespace firn {
namespace {

constexpr double kSpacing = 0.004;

// Particles at the given (x, y), z = 0, in a view over their columns.
struct Particles {
  std::vector<double> x, y, z;
  ParticleView<double> view() {
    ParticleView<double> pv{};
    pv.x[0] = x.data(), pv.x[1] = y.data(), pv.x[2] = z.data();
    pv.n = x.size();
    return pv;
  }
  void row(int first, int last, double height) {
    for (int i = first; i <= last; ++i) x.push_back(i * kSpacing), y.push_back(height), z.push_back(0);
  }
};

Collider<double> road(double height) {
  Collider<double> plane;  // the solid y <= height
  plane.center[1] = height;
  return plane;
}

TEST(ContactPatch, TheTouchingRowsCubesFromFirstToLast) {
  Particles p;
  p.row(-12, 12, -0.0005);  // sunk into the road: touches
  p.row(-15, 14, 0.0019);   // just under h / 2 above it: its cube reaches the road
  p.row(-20, 20, 0.0021);   // just over: does not
  // From the cube of x = -15 h to that of x = 14 h: 29 spacings between the centres, plus one.
  EXPECT_NEAR(contact_patch_length(p.view(), 0, p.x.size(), road(0), kSpacing), 30 * kSpacing, 1e-12);
}

TEST(ContactPatch, OnlyTheGivenParticlesAndTheRoadWhereItIs) {
  Particles p;
  p.row(-5, 5, 0.010);   // the tread, on a road raised to y = 0.01
  p.row(-30, 30, -0.1);  // other particles, deep below: not the tread's
  const std::size_t tread = 11;
  EXPECT_NEAR(contact_patch_length(p.view(), 0, tread, road(0.010), kSpacing), 11 * kSpacing, 1e-12);
  EXPECT_EQ(contact_patch_length(p.view(), 0, tread, road(0), kSpacing), 0.0);  // 10 mm above: no contact
  EXPECT_EQ(contact_patch_length(p.view(), 0, 0, road(0.010), kSpacing), 0.0);
}

}  // namespace
}  // namespace firn
