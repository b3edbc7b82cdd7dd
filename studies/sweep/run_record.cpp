#include "studies/sweep/run_record.hpp"

#include <cstdlib>
#include <stdexcept>

#include "engine/output/atomic_file.hpp"

namespace firn::sweep {

std::optional<std::string> file_text(const std::string& path) {
  try {
    return read_text_file(path);
  } catch (const std::runtime_error&) {
    return std::nullopt;
  }
}

namespace {

std::optional<double> number(const std::optional<std::string>& text) {
  if (!text || text->empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text->c_str(), &end);
  if (*end) return std::nullopt;
  return v;
}

}  // namespace

std::optional<std::string> json_value(const std::string& json, const std::string& key) {
  const std::string quoted = "\"" + key + "\"";
  for (auto at = json.find(quoted); at != std::string::npos; at = json.find(quoted, at + 1)) {
    std::size_t i = json.find_first_not_of(" \t\r\n", at + quoted.size());
    if (i == std::string::npos || json[i] != ':') continue;  // a string value equal to the key
    i = json.find_first_not_of(" \t\r\n", i + 1);
    if (i == std::string::npos) return std::nullopt;
    if (json[i] == '"') {
      std::string value;
      for (++i; i < json.size() && json[i] != '"'; ++i) {
        if (json[i] == '\\' && i + 1 < json.size()) {
          const char e = json[++i];
          value += e == 'n' ? '\n' : e == 't' ? '\t' : e;
        } else {
          value += json[i];
        }
      }
      return value;
    }
    const std::size_t end = json.find_first_of(",}\r\n", i);
    std::string value = json.substr(i, end == std::string::npos ? std::string::npos : end - i);
    value.erase(value.find_last_not_of(" \t") + 1);
    if (value == "null") return std::nullopt;
    return value;
  }
  return std::nullopt;
}

void read_run_outputs(const std::string& dir, RunRecord& record) {
  if (const auto summary = file_text(dir + "/summary.json")) {
    record.status = json_value(*summary, "status").value_or("failed");
    record.steps = number(json_value(*summary, "steps"));
    record.particles = number(json_value(*summary, "particles"));
    record.wall_seconds = number(json_value(*summary, "wall_seconds"));
    record.particle_steps_per_second = number(json_value(*summary, "particle_steps_per_second"));
  }
  if (const auto metrics = file_text(dir + "/metrics.csv")) {
    try {
      record.metrics = parse_metrics_csv(*metrics);
    } catch (const std::runtime_error&) {
      record.metrics.reset();
    }
  }
}

}  // namespace firn::sweep
