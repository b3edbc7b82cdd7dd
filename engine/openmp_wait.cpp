#include "engine/openmp_wait.hpp"

#include <cstdio>
#include <cstdlib>

namespace firn {

namespace {
std::string& recorded() {
  static std::string choice;
  return choice;
}
}  // namespace

int runnable_tasks(const std::string& loadavg) {
  int runnable = -1;
  return std::sscanf(loadavg.c_str(), "%*f %*f %*f %d/", &runnable) == 1 ? runnable : -1;
}

bool spin_while_waiting(int others, int cpus, int threads) { return others >= 0 && others + threads <= cpus; }

std::string openmp_wait() {
  if (!recorded().empty()) return recorded();
  if (const char* spin = std::getenv("GOMP_SPINCOUNT")) return std::string("spin:") + spin;
  if (const char* policy = std::getenv("OMP_WAIT_POLICY")) return policy;
  return "libgomp_default";
}

void record_openmp_wait(const std::string& choice) { recorded() = choice; }

}  // namespace firn
