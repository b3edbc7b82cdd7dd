#include "apps/launch_table.hpp"

#include <algorithm>
#include <cstdio>
#include <utility>
#include <vector>

namespace firn::app {

void print_launch_table(const std::map<std::string, backend::LaunchProfile::Entry>& launches, double loop_seconds,
                        long steps) {
  std::vector<std::pair<std::string, backend::LaunchProfile::Entry>> rows(launches.begin(), launches.end());
  std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.second.seconds > b.second.seconds; });
  const double per_step = steps > 0 ? 1.0 / double(steps) : 0;
  double in_launches = 0;
  for (const auto& [name, e] : rows) {
    std::printf("launch %-32s %10.4f ms/step %8.1f launches/step\n", name.c_str(), 1e3 * e.seconds * per_step,
                double(e.launches) * per_step);
    in_launches += e.seconds;
  }
  std::printf("launch %-32s %10.4f ms/step\n", "(outside launches)", 1e3 * (loop_seconds - in_launches) * per_step);
}

}  // namespace firn::app
