// Memory spaces (kernels/backend/memory_space.hpp): a container allocates in the default space of
// when it was constructed and keeps it, so a simulation built under a backend's space keeps its
// buffers there; the space changes where the bytes live, never the results.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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

// The VmFlags of the mapping of this process holding address a ("" where none holds it).
std::string mapping_flags(const void* a) {
  const auto at = reinterpret_cast<std::uintptr_t>(a);
  std::ifstream smaps("/proc/self/smaps");
  bool holds = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> begin >> dash >> end && dash == '-' && line.find(' ') != std::string::npos) {
      holds = begin <= at && at < end;
    } else if (holds && line.rfind("VmFlags:", 0) == 0) {
      return line;
    }
  }
  return "";
}

TEST(MemorySpace, LargeHostBuffersLieInHugePagesWithStaggeredStarts) {
#if !defined(__linux__)
  GTEST_SKIP() << "huge pages are asked for on Linux only";
#endif
  if (!backend::memory_detail::transparent_huge_pages()) GTEST_SKIP() << "transparent huge pages are off";
  constexpr std::size_t kBytes = std::size_t(3) << 19;  // 1.5 MiB: 393,216 floats
  std::set<std::uintptr_t> l1_sets, page_offsets;
  std::vector<char*> buffers;
  for (int b = 0; b < 3; ++b) {
    char* p = static_cast<char*>(backend::kHostMemory.allocate(kBytes));
    buffers.push_back(p);
    const auto a = reinterpret_cast<std::uintptr_t>(p);
    EXPECT_EQ(a % 64, 0u);
    l1_sets.insert((a >> 6) % 64);                  // the set of a 64-set L1 (bits 6-11)
    page_offsets.insert(a % (std::size_t(2) << 20));  // where it starts in its 2 MiB page
    std::memset(p, b + 1, kBytes);                  // every byte can be written
    EXPECT_NE(mapping_flags(p).find(" hg"), std::string::npos) << mapping_flags(p);  // asked for: MADV_HUGEPAGE
    EXPECT_NE(mapping_flags(p + kBytes - 1).find(" hg"), std::string::npos);
  }
  EXPECT_EQ(l1_sets.size(), 3u);  // the same particle of three columns in three different sets
  EXPECT_EQ(page_offsets.size(), 3u);
  for (int b = 0; b < 3; ++b) {
    EXPECT_EQ(buffers[b][0], b + 1);
    EXPECT_EQ(buffers[b][kBytes - 1], b + 1);
    backend::kHostMemory.deallocate(buffers[b], kBytes);
    // Unmapped, from its page's start to the end of its last page.
    const std::size_t page = std::size_t(2) << 20, offset = reinterpret_cast<std::uintptr_t>(buffers[b]) % page;
    EXPECT_EQ(mapping_flags(buffers[b]), "");
    EXPECT_EQ(mapping_flags(buffers[b] - offset), "");
    EXPECT_EQ(mapping_flags(buffers[b] - offset + (offset + kBytes + page - 1) / page * page - 1), "");
  }
  void* small = backend::kHostMemory.allocate(1000);  // small buffers: aligned to a line
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(small) % 64, 0u);
  backend::kHostMemory.deallocate(small, 1000);
}

}  // namespace
}  // namespace firn
