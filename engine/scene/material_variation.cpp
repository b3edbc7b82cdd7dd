#include "engine/scene/material_variation.hpp"

#include <algorithm>
#include <optional>
#include <sstream>

namespace firn {
namespace {

const char* const kModuli[4] = {"E", "nu", "K", "G"};
const int kPartner[4] = {1, 0, 3, 2};  // E with nu, K with G

std::string number_text(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

// The moduli with the varied ones scaled, each paired with its partner where it varies alone.
ElasticModuli varied_moduli(const ElasticModuli& m, const MaterialVariation& v, double n) {
  const double nominal[4] = {m.E, m.nu, m.K, m.G};
  std::optional<double> given[4];
  std::string blame;
  for (int i = 0; i < 4; ++i) {
    const auto a = v.amplitudes.find(kModuli[i]);
    if (a == v.amplitudes.end()) continue;
    given[i] = nominal[i] * (1 + a->second * n);
    blame = kModuli[i];
  }
  if (blame.empty()) return m;
  const int count = int(std::count_if(given, given + 4, [](const auto& g) { return g.has_value(); }));
  if (count > 2) throw VariationError(blame, "at most two of E, nu, K, G may vary");
  if (count == 1) {
    const int i = int(std::find_if(given, given + 4, [](const auto& g) { return g.has_value(); }) - given);
    given[kPartner[i]] = nominal[kPartner[i]];
  }
  try {
    return ElasticModuli::from_any_two(given[0], given[1], given[2], given[3]);
  } catch (const std::invalid_argument& e) {
    throw VariationError(blame, "at n = " + number_text(n) + ": " + e.what());
  }
}

}  // namespace

int noise_level(double n, int levels) {
  return std::clamp(int(std::floor((n + 1) / 2 * levels)), 0, levels - 1);
}

double level_centre(int level, int levels) { return -1 + (2.0 * level + 1) / levels; }

MaterialInfo material_level(const MaterialInfo& nominal, const MaterialVariation& v, int level) {
  const double n = level_centre(level, v.levels);
  MaterialInfo m = nominal;
  m.name = nominal.name + "~" + std::to_string(level);
  m.moduli = varied_moduli(nominal.moduli, v, n);
  const MaterialModelSpec* model = find_material_model(nominal.model);
  for (const auto& [key, amplitude] : v.amplitudes) {
    const double factor = 1 + amplitude * n;
    if (key == "density") {
      m.density = nominal.density * factor;
      continue;
    }
    for (const MaterialParameter& p : model->parameters) {
      if (p.key != key) continue;
      const double value = material_param(nominal, key) * factor;
      if (!(value >= p.min && value <= p.max))
        throw VariationError(key, "gives " + key + " = " + number_text(value) + " at n = " + number_text(n) +
                                      ", outside [" + number_text(p.min) + ", " + number_text(p.max) + "]");
      m.params[key] = value;
    }
  }
  return m;
}

}  // namespace firn
