#include "tests/fuzz/fuzz_input.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "engine/scene/scene_reader.hpp"
#include "engine/scene/units.hpp"

namespace firn::fuzz {
namespace {

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

std::string unusable(const SceneSpec& s) {
  const SimulationConfig& c = s.config;
  if (!(std::isfinite(c.dx) && c.dx > 0)) return "dx is not finite and positive";
  if (!(std::isfinite(c.cfl) && c.cfl > 0)) return "cfl is not finite and positive";
  if (!(std::isfinite(s.end_time) && s.end_time >= 0)) return "end_time is not finite and >= 0";
  if (!(std::isfinite(s.frame_interval) && s.frame_interval > 0)) return "frame_interval is not finite and positive";
  for (int d = 0; d < 3; ++d)
    if (!std::isfinite(c.domain_min[d]) || !std::isfinite(c.domain_max[d]) || !std::isfinite(c.gravity[d]))
      return "the domain or gravity is not finite";
  return "";
}

std::string load(const std::string& text, const std::vector<std::string>& overrides) {
  try {
    return unusable(load_scene_text(text, "fuzz.toml", SceneOptions{overrides, false}).spec);
  } catch (const SceneError&) {
    return "";
  }
}

}  // namespace

std::string check_input(const std::string& input, const std::string& base_scene) {
  if (starts_with(input, "unit:")) {
    for (int q = 0; q <= int(Quantity::moment_of_inertia); ++q) try {
        if (!std::isfinite(parse_quantity(input.substr(5), Quantity(q)))) return "the quantity is not finite";
      } catch (const std::invalid_argument&) {
      }
    return "";
  }
  if (starts_with(input, "set:")) {
    std::vector<std::string> overrides;
    std::istringstream lines(input.substr(4));
    for (std::string line; std::getline(lines, line);) overrides.push_back(line);
    return load(base_scene, overrides);
  }
  return load(input, {});
}

}  // namespace firn::fuzz
