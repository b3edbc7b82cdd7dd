// Memory spaces (kernels/backend/memory_space.hpp): a container allocates in the default space of
// when it was constructed and keeps it, so a simulation built under a backend's space keeps its
// buffers there; the space changes where the bytes live, never the results.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <utility>

#include "engine/aligned_vector.hpp"
#include "kernels/backend/serial.hpp"
#include "studies/bench/reference_problems.hpp"

namespace firn {
namespace {

// A host space that records its live allocations: [address, address + bytes).
std::map<std::uintptr_t, std::size_t>& live() {
  static std::map<std::uintptr_t, std::size_t> allocations;
  return allocations;
}
void* tracked_allocate(std::size_t bytes) {
  void* p = backend::kHostMemory.allocate(bytes);
  live()[reinterpret_cast<std::uintptr_t>(p)] = bytes;
  return p;
}
void tracked_deallocate(void* p, std::size_t bytes) {
  live().erase(reinterpret_cast<std::uintptr_t>(p));
  backend::kHostMemory.deallocate(p, bytes);
}
constexpr backend::MemorySpace kTracked{"tracked", tracked_allocate, tracked_deallocate};

bool in_tracked(const void* p) {
  const auto a = reinterpret_cast<std::uintptr_t>(p);
  auto it = live().upper_bound(a);
  if (it == live().begin()) return false;
  --it;
  return a < it->first + it->second;
}

TEST(MemorySpace, ContainersKeepTheSpaceTheyWereMadeIn) {
  AlignedVector<float> host(100);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(host.data()) % 64, 0u);
  EXPECT_FALSE(in_tracked(host.data()));
  AlignedVector<float> tracked;
  {
    const backend::UseMemorySpace scope(kTracked);
    EXPECT_STREQ(backend::default_memory_space().name, "tracked");
    {
      const backend::UseMemorySpace inner(backend::kHostMemory);  // scopes nest
      EXPECT_STREQ(backend::default_memory_space().name, "host");
    }
    EXPECT_STREQ(backend::default_memory_space().name, "tracked");
    tracked = AlignedVector<float>(10);
    EXPECT_TRUE(in_tracked(tracked.data()));
  }
  EXPECT_STREQ(backend::default_memory_space().name, "host");
  tracked.resize(100000);  // regrows in its own space after the scope
  EXPECT_TRUE(in_tracked(tracked.data()));
  host.swap(tracked);  // the storage moves with its space
  EXPECT_TRUE(in_tracked(host.data()));
  EXPECT_FALSE(in_tracked(tracked.data()));
  host = AlignedVector<float>();
  EXPECT_TRUE(live().empty());
}

std::uint64_t drop_cube(const backend::MemorySpace& space, bool check_buffers) {
  const backend::UseMemorySpace scope(space);
  SimulationConfig c = cube_drop_config(1);
  c.dx = 0.02;
  Simulation<float, backend::Serial> sim(c);
  add_cube_drop_particles(sim, cube_drop_material());
  for (int s = 0; s < 5; ++s) sim.step();
  if (check_buffers) {
    const ParticleView<float> pv = sim.particles();
    for (const void* column : {(const void*)pv.x[0], (const void*)pv.v[2], (const void*)pv.F[8], (const void*)pv.mass})
      EXPECT_TRUE(in_tracked(column));
    EXPECT_TRUE(in_tracked(sim.grid().slot_coords(0)));
  }
  return sim.state_hash();
}

TEST(MemorySpace, ASimulationKeepsItsBuffersInItsSpaceAndItsResults) {
  const std::uint64_t tracked = drop_cube(kTracked, true);
  EXPECT_EQ(tracked, drop_cube(backend::kHostMemory, false));
  EXPECT_TRUE(live().empty());
}

}  // namespace
}  // namespace firn
