#include "engine/output/run_summary.hpp"

#include <sys/resource.h>

#include <cstdio>
#include <sstream>

namespace firn {
namespace {

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (c == '\n') out += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else out += c;
  }
  return out + "\"";
}

}  // namespace

std::string RunSummary::to_json() const {
  std::ostringstream j;
  j.precision(10);
  j << "{\n  \"status\": " << json_string(status) << ",\n  \"error\": " << (error.empty() ? "null" : json_string(error))
    << ",\n  \"steps\": " << steps << ",\n  \"particles\": " << particles << ",\n  \"simulated_time\": " << simulated_time
    << ",\n  \"wall_seconds\": " << wall_seconds << ",\n  \"step_seconds\": " << step_seconds
    << ",\n  \"particle_steps_per_second\": " << particle_steps_per_second() << ",\n  \"threads\": " << threads
    << ",\n  \"openmp_wait\": " << json_string(openmp_wait) << ",\n  \"backend\": " << json_string(backend)
    << ",\n  \"precision\": " << json_string(precision)
    << ",\n  \"peak_memory_mb\": " << peak_memory_mb << ",\n  \"state_hash\": " << json_string(state_hash);
  if (!launches.empty()) {
    j << ",\n  \"launch_seconds\": {";
    const char* separator = "\n    ";
    for (const auto& [name, entry] : launches) {
      j << separator << json_string(name) << ": " << entry.seconds;
      separator = ",\n    ";
    }
    j << "\n  }";
  }
  j << "\n}\n";
  return j.str();
}

double peak_memory_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;  // ru_maxrss is in kB on Linux
}

}  // namespace firn
