#include "engine/scene/scene_reader.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <deque>
#include <map>
#include <optional>
#include <sstream>

#include "engine/material_catalog.hpp"
#include "engine/scene/scene_schema.hpp"
#include "kernels/step/mirror_walls.hpp"
#include "kernels/step/penalty_contact.hpp"

namespace firn {
namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (std::tolower(a[i - 1]) != std::tolower(b[j - 1]))});
      diag = up;
    }
  }
  return row[b.size()];
}

// " (did you mean 'x'?)" for the closest candidate within a third of the word's length, or "".
std::string suggestion(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_d) best = c, best_d = d;
  }
  return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
  return s;
}

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date or time";
  }
}

std::string number_text(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

// Where messages point: the file position of a node, or the --set that put it there.
struct Context {
  std::string file;
  std::map<std::string, std::string> overrides;  // full key -> the --set argument

  std::string where(const toml::node* node, const toml::source_region& fallback, const std::string& key) const {
    for (auto it = overrides.rbegin(); it != overrides.rend(); ++it)
      if (key == it->first || key.rfind(it->first + ".", 0) == 0) return "--set " + it->second;
    const toml::source_region& r = node && node->source().begin.line ? node->source() : fallback;
    return file + ":" + std::to_string(r.begin.line) + ":" + std::to_string(r.begin.column);
  }
  [[noreturn]] void fail(const toml::node* node, const toml::source_region& fallback, const std::string& key,
                         const std::string& message) const {
    throw SceneError(where(node, fallback, key) + ": " + key + ": " + message);
  }
};

// Reads one table against its section's keys, converting to SI and recording every value used
// (defaults included) into `out`. finish() rejects the keys nobody read.
class TableReader {
 public:
  // `positions`: the table as parsed from the file, when `table` is a merged copy (a material
  // with a preset) whose nodes have lost their file positions.
  TableReader(const Context& ctx, const toml::table& table, const SectionSpec& section, std::string prefix,
              toml::table& out, const toml::table* positions = nullptr)
      : ctx_(ctx), table_(table), positions_(positions ? *positions : table), section_(section),
        prefix_(std::move(prefix)), out_(out) {}

  // Keys with an `applies_to` (a shape, a model, a mode) are read only where it is one of the
  // filters: set_filter starts the list, add_filter adds another (a [tire]'s axle and spin).
  void set_filter(const std::string& f) { filters_ = {f}; }
  void add_filter(const std::string& f) { filters_.push_back(f); }
  bool has(const std::string& key) const { return table_.contains(key); }
  std::string full(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }
  const toml::source_region& source() const { return table_.source(); }
  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    ctx_.fail(positions_.get(key), positions_.source(), full(key), message);
  }
  std::string where(const std::string& key) const {
    return ctx_.where(positions_.get(key), positions_.source(), full(key));
  }

  double number(const std::string& key) {
    const KeySpec& k = spec(key);
    const toml::node* n = value(k);
    const double v = to_number(*n, k, key);
    check_range(k, key, v);
    out_.insert_or_assign(key, v);
    return v;
  }
  std::optional<double> optional_number(const std::string& key) {
    if (!has(key)) {
      used_.push_back(key);
      return std::nullopt;
    }
    return number(key);
  }
  long long integer(const std::string& key) {
    const KeySpec& k = spec(key);
    const toml::node* n = value(k);
    if (!n->is_integer()) fail(key, "expected an integer, got " + type_name(*n));
    const long long v = n->as_integer()->get();
    check_range(k, key, double(v));
    out_.insert_or_assign(key, v);
    return v;
  }
  Point vec3(const std::string& key) {
    const KeySpec& k = spec(key);
    const toml::node* n = value(k);
    const toml::array* a = n->as_array();
    if (!a || a->size() != 3)
      fail(key, std::string("expected [x, y, z] in ") + si_unit(k.quantity) + ", got " +
                    (a ? "an array of " + std::to_string(a->size()) : type_name(*n)));
    Point p;
    toml::array o;
    for (int d = 0; d < 3; ++d) {
      p[d] = to_number(*a->get(std::size_t(d)), k, key);
      if (!std::isfinite(p[d])) fail(key, std::string("must be finite (") + "xyz"[d] + " is " + number_text(p[d]) + ")");
      o.push_back(p[d]);
    }
    out_.insert_or_assign(key, o);
    return p;
  }
  std::optional<Point> optional_vec3(const std::string& key) {
    if (!has(key)) {
      used_.push_back(key);
      return std::nullopt;
    }
    return vec3(key);
  }
  bool boolean(const std::string& key) {
    const KeySpec& k = spec(key);
    const toml::node* n = value(k);
    if (!n->is_boolean()) fail(key, "expected true or false, got " + type_name(*n));
    out_.insert_or_assign(key, n->as_boolean()->get());
    return n->as_boolean()->get();
  }
  // An upper corner `hi` read from `key` must exceed the lower corner read from `lo_key`.
  void require_above(const std::string& key, const Point& hi, const std::string& lo_key, const Point& lo) const {
    for (int d = 0; d < 3; ++d)
      if (!(hi[d] > lo[d])) fail(key, "must exceed " + lo_key + " in every component");
  }
  std::string choice(const std::string& key) {
    const KeySpec& k = spec(key);
    const toml::node* n = value(k);
    if (!n->is_string()) fail(key, "expected one of " + join(k.choices) + ", got " + type_name(*n));
    const std::string v = n->as_string()->get();
    if (std::find(k.choices.begin(), k.choices.end(), v) == k.choices.end())
      fail(key, "'" + v + "' is not one of " + join(k.choices) + suggestion(v, k.choices));
    out_.insert_or_assign(key, v);
    return v;
  }
  int choice_index(const std::string& key) {
    const std::string v = choice(key);
    const auto& c = spec(key).choices;
    return int(std::find(c.begin(), c.end(), v) - c.begin());
  }
  std::optional<std::string> text(const std::string& key) {
    const KeySpec& k = spec(key);
    const toml::node* n = value(k);
    if (!n) return std::nullopt;
    if (!n->is_string()) fail(key, "expected a string, got " + type_name(*n));
    out_.insert_or_assign(key, n->as_string()->get());
    return n->as_string()->get();
  }
  // An optional sub-table (null where absent); the caller reads it with a TableReader of its own.
  const toml::table* table(const std::string& key) {
    const KeySpec& k = spec(key);
    const toml::node* n = value(k);
    if (n && !n->is_table()) fail(key, "expected a table, got " + type_name(*n));
    return n ? n->as_table() : nullptr;
  }
  const toml::array& tables(const std::string& key) {
    const KeySpec& k = spec(key);
    const toml::node* n = value(k);
    if (!n->is_array_of_tables() || n->as_array()->empty())
      fail(key, "expected a non-empty array of tables, got " + type_name(*n));
    return *n->as_array();
  }

  void finish() const {
    for (const auto& [name, node] : table_) {
      const std::string key(name.str());
      if (std::find(used_.begin(), used_.end(), key) != used_.end()) continue;
      std::vector<std::string> applicable, elsewhere;
      for (const KeySpec& k : section_.keys) {
        if (applies(k)) applicable.push_back(k.key);
        else if (k.key == key) elsewhere.push_back(k.applies_to);
      }
      if (!elsewhere.empty())
        fail(key, "does not apply to " + quoted(filters_) + " (only to " + quoted(elsewhere) + ")");
      fail(key, "unknown key" + suggestion(key, applicable));
    }
  }

 private:
  const KeySpec& spec(const std::string& key) {
    used_.push_back(key);
    for (const KeySpec& k : section_.keys)
      if (k.key == key && applies(k)) return k;
    throw std::logic_error("scene schema has no key " + section_.name + "." + key + " for " + quoted(filters_));
  }
  bool applies(const KeySpec& k) const {
    return k.applies_to.empty() || std::find(filters_.begin(), filters_.end(), k.applies_to) != filters_.end();
  }
  static std::string quoted(const std::vector<std::string>& v) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", '" : "'") + v[i] + "'";
    return s;
  }
  // The node given, or the default parsed from the schema; null for an absent optional key.
  const toml::node* value(const KeySpec& k) {
    if (const toml::node* n = table_.get(k.key)) return n;
    if (!k.default_toml.empty()) {
      defaults_.push_back(toml::parse("v = " + k.default_toml));
      return defaults_.back().get("v");
    }
    if (k.required) fail(k.key, "missing (required" + (k.applies_to.empty() ? "" : " for '" + k.applies_to + "'") + ")");
    return nullptr;
  }
  double to_number(const toml::node& n, const KeySpec& k, const std::string& key) const {
    if (n.is_integer()) return double(n.as_integer()->get());
    if (n.is_floating_point()) return n.as_floating_point()->get();
    if (n.is_string()) {
      try {
        return parse_quantity(n.as_string()->get(), k.quantity);
      } catch (const std::invalid_argument& e) {
        fail(key, e.what());
      }
    }
    fail(key, std::string("expected a ") + quantity_name(k.quantity) +
                  (k.quantity == Quantity::dimensionless ? "" : std::string(" (") + si_unit(k.quantity) + ")") +
                  ", got " + type_name(n));
  }
  void check_range(const KeySpec& k, const std::string& key, double v) const {
    // Infinity only where it is the default, meaning "no limit" (e.g. Jp_max).
    const bool unlimited = std::isinf(v) && (k.default_toml == "inf" || k.default_toml == "-inf");
    if (!std::isfinite(v) && !unlimited) fail(key, "must be finite");
    const bool below = k.min_exclusive ? !(v > k.min) : !(v >= k.min);
    const bool above = k.max_exclusive ? !(v < k.max) : !(v <= k.max);
    if (below || above) {
      std::string r;
      if (k.max == std::numeric_limits<double>::infinity())
        r = std::string(k.min_exclusive ? "> " : ">= ") + number_text(k.min);
      else
        r = "in " + std::string(k.min_exclusive ? "(" : "[") + number_text(k.min) + ", " + number_text(k.max) +
            (k.max_exclusive ? ")" : "]");
      fail(key, "must be " + r + " (got " + number_text(v) + ")");
    }
  }

  const Context& ctx_;
  const toml::table& table_;
  const toml::table& positions_;
  const SectionSpec& section_;
  std::string prefix_;
  toml::table& out_;
  std::vector<std::string> filters_;
  std::vector<std::string> used_;
  std::deque<toml::table> defaults_;
};

const toml::table& subtable(const Context& ctx, const toml::table& root, const std::string& name, toml::table& empty) {
  const toml::node* n = root.get(name);
  if (!n) return empty;
  if (!n->is_table()) ctx.fail(n, root.source(), name, "expected a table [" + name + "], got " + type_name(*n));
  return *n->as_table();
}

// The index of the material named by the table's `material` key.
int material_index(TableReader& r, const std::vector<MaterialInfo>& materials, const char* key = "material") {
  const std::string material = *r.text(key);
  std::vector<std::string> names;
  for (const auto& m : materials) names.push_back(m.name);
  const auto it = std::find(names.begin(), names.end(), material);
  if (it == names.end())
    r.fail(key, "no material '" + material + "' (defined: " + join(names) + ")" + suggestion(material, names));
  return int(it - names.begin());
}

Friction<double> read_friction(TableReader& r) {
  Friction<double> f;
  f.law = FrictionLaw(r.choice_index("friction_law"));
  f.mu = r.number("friction");
  return f;
}

// A penalty contact (kernels/step/penalty_contact.hpp) only pushes, and its spring, omega dt up to
// penalty_stiffness cfl, must stay below the engine's bound.
void check_penalty(TableReader& r, WallType boundary, double stiffness, double cfl) {
  if (boundary != WallType::separate) r.fail("contact", "penalty needs boundary = \"separate\": it only pushes");
  if (stiffness * cfl >= kPenaltyStableOmegaDt) {
    std::ostringstream m;
    m << "times simulation.cfl is " << stiffness * cfl << ", and must stay below " << kPenaltyStableOmegaDt
      << " for the spring to be stable";
    r.fail("penalty_stiffness", m.str());
  }
}

BodyShape read_shape(const Context& ctx, TableReader& r, toml::table& out, const std::string& prefix) {
  BodyShape s;
  const std::string kind = r.choice("shape");
  r.set_filter(kind);
  if (kind == "sphere") {
    s.kind = BodyShape::Kind::sphere;
    s.center = r.vec3("center");
    s.radius = r.number("radius");
  } else if (kind == "box") {
    s.kind = BodyShape::Kind::box;
    s.min = r.vec3("min");
    s.max = r.vec3("max");
    r.require_above("max", s.max, "min", s.min);
  } else if (kind == "cylinder") {
    s.kind = BodyShape::Kind::cylinder;
    s.center = r.vec3("center");
    s.radius = r.number("radius");
    s.length = r.number("length");
    s.axis = r.choice_index("axis");
  } else {
    s.kind = kind == "union" ? BodyShape::Kind::union_of : BodyShape::Kind::difference_of;
    toml::array parts_out;
    const toml::array& parts = r.tables("parts");
    for (std::size_t i = 0; i < parts.size(); ++i) {
      toml::table part_out;
      TableReader pr(ctx, *parts.get(i)->as_table(), scene_section("bodies.parts"),
                     prefix + ".parts." + std::to_string(i), part_out);
      s.parts.push_back(read_shape(ctx, pr, part_out, prefix + ".parts." + std::to_string(i)));
      pr.finish();
      parts_out.push_back(std::move(part_out));
    }
    out.insert_or_assign("parts", std::move(parts_out));
  }
  return s;
}

// Applies "a.b.c=value" to the parsed file; numeric path parts index arrays ("bodies.0.velocity").
void apply_override(Context& ctx, toml::table& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw SceneError("--set " + assignment + ": expected KEY=VALUE, e.g. simulation.dx=0.002");
  const std::string key = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  std::vector<std::string> parts;
  for (std::size_t b = 0;;) {
    const auto e = key.find('.', b);
    parts.push_back(key.substr(b, e - b));
    if (e == std::string::npos) break;
    b = e + 1;
  }
  // The value as TOML; where it is not TOML, the plain string (so `--set tire.speed=5 mph` works).
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
    parsed.insert("v", text);
  }
  toml::node* at = &root;
  std::string path;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    path += (i ? "." : "") + part;
    const bool last = i + 1 == parts.size();
    if (toml::table* t = at->as_table()) {
      if (last) {
        t->insert_or_assign(part, *parsed.get("v"));
        break;
      }
      if (!t->contains(part)) t->insert(part, toml::table{});
      at = t->get(part);
    } else if (toml::array* a = at->as_array()) {
      char* end = nullptr;
      const unsigned long index = std::strtoul(part.c_str(), &end, 10);
      if (part.empty() || *end || index >= a->size())
        throw SceneError("--set " + assignment + ": " + path + ": no element " + part + " (the array has " +
                         std::to_string(a->size()) + ")");
      if (last) {
        a->replace(a->begin() + long(index), *parsed.get("v"));
        break;
      }
      at = a->get(index);
    } else {
      throw SceneError("--set " + assignment + ": " + path + ": is a value, not a table");
    }
  }
  ctx.overrides[key] = assignment;
}

// A material's `vary` table (engine/scene/material_variation.hpp), checked at every level.
MaterialVariation read_variation(const Context& ctx, TableReader& material, const toml::table& vary,
                                 const toml::table& given, const MaterialInfo& info, toml::table& out) {
  const toml::node* positions = given.get("vary");
  const SectionSpec& section = scene_section("materials.NAME.vary");
  TableReader r(ctx, vary, section, "materials." + info.name + ".vary", out,
                positions && positions->is_table() ? positions->as_table() : nullptr);
  r.set_filter(info.model);
  MaterialVariation v;
  v.scale = r.number("scale");
  v.seed = std::uint64_t(r.integer("seed"));
  v.levels = int(r.integer("levels"));
  for (const KeySpec& k : section.keys) {
    const bool amplitude = k.key != "scale" && k.key != "seed" && k.key != "levels";
    if (amplitude && (k.applies_to.empty() || k.applies_to == info.model) && r.has(k.key))
      v.amplitudes[k.key] = r.number(k.key);
  }
  r.finish();
  if (!v.varied()) material.fail("vary", "names no parameter to vary (e.g. density = 0.1)");
  for (int level = 0; level < v.levels; ++level) {
    try {
      make_material_model<double>(material_level(info, v, level));  // constraints between parameters
    } catch (const VariationError& e) {
      r.fail(e.key, e.what());
    } catch (const std::invalid_argument& e) {
      material.fail("vary", "level " + std::to_string(level) + ": " + e.what());
    }
  }
  return v;
}

MaterialInfo read_material(const Context& ctx, const std::string& name, const toml::table& given, toml::table& out,
                           std::optional<Point>& color, MaterialVariation& variation, int& contact_group) {
  const std::string prefix = "materials." + name;
  // Merge the preset's values under the scene's keys.
  toml::table merged = given;
  const MaterialPreset* preset = nullptr;
  if (const toml::node* p = given.get("preset")) {
    if (!p->is_string()) ctx.fail(p, given.source(), prefix + ".preset", "expected a string, got " + type_name(*p));
    const std::string pname = p->as_string()->get();
    preset = find_material_preset(pname);
    if (!preset) {
      std::vector<std::string> names;
      for (const auto& q : material_presets()) names.push_back(q.name);
      ctx.fail(p, given.source(), prefix + ".preset", "unknown preset '" + pname + "'" + suggestion(pname, names));
    }
    const bool own_moduli = given.contains("E") || given.contains("nu") || given.contains("K") || given.contains("G");
    if (!given.contains("model")) merged.insert("model", preset->model);
    const MaterialModelSpec* spec = find_material_model(preset->model);
    for (const auto& [key, value] : preset->values) {
      const bool modulus = key == "E" || key == "nu" || key == "K" || key == "G";
      if (given.contains(key) || (modulus && own_moduli)) continue;
      const MaterialParameter* param = nullptr;
      for (const auto& q : spec->parameters)
        if (q.key == key) param = &q;
      if (param && !param->choices.empty()) merged.insert(key, param->choices.at(std::size_t(value)));
      else merged.insert(key, value);
    }
  }
  TableReader r(ctx, merged, scene_section("materials.NAME"), prefix, out, &given);
  r.text("preset");
  out.erase("preset");  // the resolved scene spells the values out
  if (!merged.contains("model")) r.fail("model", "missing (give `model` or `preset`)");
  MaterialInfo info;
  info.name = name;
  info.model = r.choice("model");
  r.set_filter(info.model);
  if (!merged.contains("density")) r.fail("density", "missing (required)");
  info.density = r.number("density");
  const auto E = r.optional_number("E"), nu = r.optional_number("nu"), K = r.optional_number("K"),
             G = r.optional_number("G");
  try {
    info.moduli = ElasticModuli::from_any_two(E, nu, K, G);
  } catch (const std::invalid_argument& e) {
    r.fail(E ? "E" : K ? "K" : G ? "G" : "nu", e.what());
  }
  for (const MaterialParameter& p : find_material_model(info.model)->parameters)
    info.params[p.key] = p.choices.empty() ? r.number(p.key) : double(r.choice_index(p.key));
  contact_group = int(r.integer("contact_group"));
  color = r.optional_vec3("color");
  if (color)
    for (double c : *color)
      if (!(c >= 0 && c <= 1)) r.fail("color", "each component must be in [0, 1]");
  const toml::table* vary = r.table("vary");
  r.finish();
  try {  // constraints between parameters (e.g. G2 < G) are the factory's to check
    make_material_model<double>(info);
  } catch (const std::invalid_argument& e) {
    r.fail("model", e.what());
  }
  if (vary) {
    toml::table vo;
    variation = read_variation(ctx, r, *vary, given, info, vo);
    out.insert_or_assign("vary", std::move(vo));
  }
  return info;
}

}  // namespace

int SceneSpec::per_axis() const { return int(std::lround(std::cbrt(double(particles_per_cell)))); }

namespace {

SceneError syntax_error(const std::string& path, const toml::parse_error& e) {
  const auto& b = e.source().begin;
  std::string what(e.description());
  return SceneError(path + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) + ": TOML syntax: " + what);
}

LoadedScene read_scene(const std::string& path, toml::table root, const SceneOptions& options) {
  Context ctx{path, {}};
  for (const std::string& a : options.overrides) apply_override(ctx, root, a);

  const std::vector<std::string> sections = {"simulation", "walls", "materials", "bodies",  "colliders",
                                             "tire",       "conveyor", "loads",   "contact", "metrics", "output", "render"};
  for (const auto& [name, node] : root) {
    const std::string key(name.str());
    if (std::find(sections.begin(), sections.end(), key) == sections.end())
      ctx.fail(&node, root.source(), key, "unknown section" + suggestion(key, sections));
  }

  LoadedScene loaded;
  SceneSpec& s = loaded.spec;
  s.path = path;
  {
    const auto slash = path.find_last_of('/');
    s.name = path.substr(slash == std::string::npos ? 0 : slash + 1);
    s.name = s.name.substr(0, s.name.rfind(".toml"));
  }
  toml::table out, empty;

  // [simulation]
  {
    toml::table o;
    const toml::table& t = subtable(ctx, root, "simulation", empty);
    if (!root.contains("simulation")) ctx.fail(nullptr, root.source(), "simulation", "missing section [simulation]");
    TableReader r(ctx, t, scene_section("simulation"), "simulation", o);
    SimulationConfig& c = s.config;
    c.domain_min = r.vec3("domain_min");
    c.domain_max = r.vec3("domain_max");
    r.require_above("domain_max", c.domain_max, "domain_min", c.domain_min);
    c.dx = r.number("dx");
    for (int d = 0; d < 3; ++d)
      if ((c.domain_max[d] - c.domain_min[d]) / c.dx > 1e5) r.fail("dx", "gives more than 1e5 cells along an axis");
    s.particles_per_cell = int(r.integer("particles_per_cell"));
    if (std::lround(std::pow(s.per_axis(), 3)) != s.particles_per_cell)
      r.fail("particles_per_cell", "must be a cube: 1, 8, 27 or 64 (got " + std::to_string(s.particles_per_cell) + ")");
    s.end_time = r.number("end_time");
    const auto fi = r.optional_number("frame_interval");
    s.frame_interval = fi ? *fi : s.end_time / 100;
    o.insert_or_assign("frame_interval", s.frame_interval);
    c.cfl = r.number("cfl");
    c.dt_max = r.number("dt_max");
    c.fixed_dt = r.number("fixed_dt");
    c.damping = r.number("damping");
    c.gravity = r.vec3("gravity");
    c.transfer = Transfer(r.choice_index("transfer"));
    c.flip_alpha = r.number("flip_alpha");
    c.shape = Shape(r.choice_index("shape"));
    s.precision = r.choice("precision");
    r.finish();
    if (options.preview) {
      c.dx *= 2;
      s.particles_per_cell = std::max(1, s.per_axis() / 2);
      s.particles_per_cell = s.particles_per_cell * s.particles_per_cell * s.particles_per_cell;
      s.frame_interval *= 2;
      o.insert_or_assign("dx", c.dx);
      o.insert_or_assign("particles_per_cell", s.particles_per_cell);
      o.insert_or_assign("frame_interval", s.frame_interval);
    }
    out.insert("simulation", std::move(o));
  }
  // [walls]
  {
    toml::table o;
    TableReader r(ctx, subtable(ctx, root, "walls", empty), scene_section("walls"), "walls", o);
    const WallType all = WallType(r.choice_index("type"));
    const double friction = r.number("friction");
    const int width = int(r.integer("width"));
    const bool mirror = r.boolean("mirror");
    const char* faces[6] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
    for (int f = 0; f < 6; ++f) {
      WallType type = all;
      if (r.has(faces[f])) type = WallType(r.choice_index(faces[f]));
      else o.insert_or_assign(faces[f], scene_section("walls").keys[0].choices[std::size_t(all)]);
      const bool mirrored = mirror && type != WallType::none;  // faces set to none are left alone
      const std::string why = mirrored ? mirror_wall_error(type, width, friction, s.config.nodes(f / 2)) : "";
      if (!why.empty()) r.fail("mirror", "cannot mirror the wall on " + std::string(faces[f]) + ": " + why);
      s.config.walls[f] = Wall<double>{type, width, friction, mirrored};
    }
    r.finish();
    out.insert("walls", std::move(o));
  }
  // [materials.NAME]
  {
    const toml::table& t = subtable(ctx, root, "materials", empty);
    if (t.empty()) ctx.fail(root.get("materials"), root.source(), "materials", "no materials: add a [materials.NAME] table");
    toml::table o;
    for (const auto& [name, node] : t) {
      const std::string n(name.str());
      if (!node.is_table()) ctx.fail(&node, t.source(), "materials." + n, "expected a table [materials." + n + "]");
      toml::table mo;
      s.render.material_colors.emplace_back();
      s.material_variations.emplace_back();
      s.contact_groups.emplace_back();
      s.materials.push_back(read_material(ctx, n, *node.as_table(), mo, s.render.material_colors.back(),
                                          s.material_variations.back(), s.contact_groups.back()));
      o.insert(n, std::move(mo));
    }
    out.insert("materials", std::move(o));
  }
  auto table_array = [&](const std::string& name) -> const toml::array* {
    const toml::node* n = root.get(name);
    if (!n) return nullptr;
    if (!n->is_array_of_tables()) ctx.fail(n, root.source(), name, "expected [[" + name + "]] tables, got " + type_name(*n));
    return n->as_array();
  };
  // [[bodies]]
  {
    const toml::array* a = table_array("bodies");
    const bool rubber_tire = root.at_path("tire.body").value<std::string>() == std::optional<std::string>("rubber");
    if ((!a || a->empty()) && !root.contains("conveyor") && !rubber_tire)
      ctx.fail(nullptr, root.source(), "bodies", "no bodies: add a [[bodies]] table (or a [conveyor], or a rubber [tire])");
    toml::array o;
    for (std::size_t i = 0; a && i < a->size(); ++i) {
      const std::string prefix = "bodies." + std::to_string(i);
      toml::table bo;
      TableReader r(ctx, *a->get(i)->as_table(), scene_section("bodies"), prefix, bo);
      BodySpec b;
      b.name = r.text("name").value_or("body " + std::to_string(i + 1));
      b.location = r.where("shape") + ": " + prefix;
      b.material = material_index(r, s.materials);
      b.velocity = r.vec3("velocity");
      b.angular_velocity = r.vec3("angular_velocity");
      b.jitter = r.number("jitter");
      b.seed = std::uint64_t(r.integer("seed"));
      b.shape = read_shape(ctx, r, bo, prefix);
      r.finish();
      Point lo, hi;
      b.shape.bounds(lo, hi);
      for (int d = 0; d < 3; ++d)
        if (lo[d] < s.config.domain_min[d] || hi[d] > s.config.domain_max[d])
          r.fail("shape", "body '" + b.name + "' extends outside the domain along " + "xyz"[d] + " (" +
                              number_text(lo[d]) + " to " + number_text(hi[d]) + " m, domain " +
                              number_text(s.config.domain_min[d]) + " to " + number_text(s.config.domain_max[d]) + " m)");
      s.bodies.push_back(b);
      o.push_back(std::move(bo));
    }
    if (a) out.insert("bodies", std::move(o));
  }
  // [[colliders]]
  if (const toml::array* a = table_array("colliders")) {
    toml::array o;
    for (std::size_t i = 0; i < a->size(); ++i) {
      toml::table co;
      TableReader r(ctx, *a->get(i)->as_table(), scene_section("colliders"), "colliders." + std::to_string(i), co);
      ColliderSpec c;
      c.name = r.text("name").value_or("collider" + std::to_string(i + 1));
      if (c.name.empty() || c.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") !=
                                std::string::npos)
        r.fail("name", "'" + c.name + "' must be letters, digits and _ (it names metrics.csv columns)");
      const std::string shape = r.choice("shape");
      r.set_filter(shape);
      if (shape == "plane") {
        c.kind = ColliderSpec::Kind::plane;
        c.point = r.vec3("point");
        c.normal = r.vec3("normal");
        const double len = std::sqrt(c.normal[0] * c.normal[0] + c.normal[1] * c.normal[1] + c.normal[2] * c.normal[2]);
        if (!(len > 0)) r.fail("normal", "must not be zero");
        for (double& v : c.normal) v /= len;
      } else if (shape == "box") {
        c.kind = ColliderSpec::Kind::box;
        c.min = r.vec3("min");
        c.max = r.vec3("max");
        r.require_above("max", c.max, "min", c.min);
      } else {
        c.kind = ColliderSpec::Kind::cylinder;
        c.center = r.vec3("center");
        c.radius = r.number("radius");
        c.length = r.number("length");
        c.axis = r.choice_index("axis");
      }
      c.velocity = r.vec3("velocity");
      c.angular_velocity = r.vec3("angular_velocity");
      c.boundary = WallType(r.choice_index("boundary") + 1);
      c.friction = read_friction(r);
      c.contact = ColliderContact(r.choice_index("contact"));
      c.penalty_stiffness = r.number("penalty_stiffness");
      if (c.contact == ColliderContact::penalty) check_penalty(r, c.boundary, c.penalty_stiffness, s.config.cfl);
      if (c.contact == ColliderContact::pooled) {
        if (c.boundary != WallType::separate) r.fail("contact", "pooled needs boundary = \"separate\"");
        for (const ColliderSpec& earlier : s.colliders)
          if (earlier.contact == ColliderContact::pooled) r.fail("contact", "only one collider may be pooled");
        for (const int group : s.contact_groups)
          if (group != 0) r.fail("contact", "pooled cannot be used with two contact groups");
        for (const Wall<double>& w : s.config.walls)
          if (w.mirror) r.fail("contact", "pooled cannot be used with mirror walls");
      }
      r.finish();
      s.colliders.push_back(c);
      o.push_back(std::move(co));
    }
    if (int(s.colliders.size()) > kMaxColliders)
      ctx.fail(a, root.source(), "colliders", "at most " + std::to_string(kMaxColliders) + " colliders");
    out.insert("colliders", std::move(o));
  }
  // [tire]
  if (root.contains("tire")) {
    toml::table o;
    TableReader r(ctx, subtable(ctx, root, "tire", empty), scene_section("tire"), "tire", o);
    TireSpec t;
    t.tread = r.choice("tread");
    t.center = r.vec3("center");
    t.radius = r.number("radius");
    t.width = r.number("width");
    t.tread_depth = r.number("tread_depth");
    if (!(t.tread_depth < t.radius)) r.fail("tread_depth", "must be less than the radius");
    t.pitches = int(r.integer("pitches"));
    t.shoulder = r.number("shoulder");
    if (t.shoulder > 0 && t.tread != "slick") r.fail("shoulder", "rounds a slick tire's shoulders: set tread = \"slick\"");
    if (!(t.shoulder < 0.5 * t.width && t.shoulder < t.radius))
      r.fail("shoulder", "must be less than half the width and less than the radius");
    const std::string axle = r.choice("axle"), spin = r.choice("spin"), body = r.choice("body");
    r.set_filter(axle);
    r.add_filter(spin);
    r.add_filter(body);
    t.rubber = body == "rubber";
    if (t.rubber) {
      t.material = material_index(r, s.materials);
      t.carcass_material = r.text("carcass_material") ? material_index(r, s.materials, "carcass_material") : t.material;
      t.sidewall_material =
          r.text("sidewall_material") ? material_index(r, s.materials, "sidewall_material") : t.material;
      t.carcass_radius = t.radius - t.tread_depth - r.number("carcass");
      if (!(t.carcass_radius > 0)) r.fail("carcass", "leaves no rim: tread_depth + carcass must be less than the radius");
      t.pressure = r.number("pressure");
      t.pressure_ramp = r.number("pressure_ramp");
      const std::optional<double> rim = r.optional_number("rim_radius");
      t.rim_radius = rim ? *rim : t.pressure > 0 ? kDefaultRimFraction * t.radius : t.carcass_radius;
      o.insert_or_assign("rim_radius", t.rim_radius);
      if (!(t.rim_radius <= t.carcass_radius))
        r.fail("rim_radius", "must not exceed the carcass's inner radius, radius - tread_depth - carcass");
      if (t.pressure > 0 && !(t.rim_radius < t.carcass_radius))
        r.fail("pressure", "needs an air cavity: a rim_radius below the carcass's inner radius");
      if (t.pressure > 0 && s.particles_per_cell < 8)  // measured: at 1 per cell the tire blows apart
        r.fail("pressure", "needs at least 8 particles per cell: with one, MPM tears the carcass apart under the "
                           "pressure's tension (a --preview of a scene with 8 has one)");
      const double spacing = s.config.dx / s.per_axis();
      if (t.pressure > 0 && !(t.radius - t.tread_depth - t.carcass_radius >= 2 * spacing - 1e-12))
        r.fail("carcass", "must be at least two particle spacings thick (" + number_text(2 * spacing) +
                              " m) to hold an inflation pressure");
      t.sidewall = r.number("sidewall");
      if (t.rim_radius < t.carcass_radius && !(t.sidewall < 0.5 * t.width))
        r.fail("sidewall", "must be less than half the width");
    }
    t.loaded = axle == "loaded";
    t.free_spin = spin == "free";
    if (!t.free_spin) t.speed = r.number("speed");  // a free spin's: the conveyor's, below
    if (t.loaded) t.load = r.number("load");
    if (t.loaded || t.free_spin) t.mass = r.number("mass");
    if (t.free_spin) {
      const std::optional<double> inertia = r.optional_number("inertia");
      t.inertia = inertia ? *inertia : 0.5 * t.mass * t.radius * t.radius;  // a solid disk's
      o.insert_or_assign("inertia", t.inertia);
    }
    t.boundary = WallType(r.choice_index("boundary") + 1);
    t.friction = read_friction(r);
    t.contact = r.choice_index("contact") == 1 ? ColliderContact::penalty : ColliderContact::nodes;
    t.penalty_stiffness = r.number("penalty_stiffness");
    if (t.contact == ColliderContact::penalty) {
      if (t.rubber) r.fail("contact", "penalty is a rigid tire's: a rubber tire meets the snow through its particles");
      check_penalty(r, t.boundary, t.penalty_stiffness, s.config.cfl);
    }
    r.finish();
    for (int d = 0; d < 3; ++d) {
      const double reach = d == 2 ? 0.5 * t.width : t.radius;
      if (t.center[d] - reach < s.config.domain_min[d] || t.center[d] + reach > s.config.domain_max[d])
        r.fail("center", std::string("the tire extends outside the domain along ") + "xyz"[d]);
    }
    s.tire = t;
    out.insert("tire", std::move(o));
  }
  // [conveyor]
  if (root.contains("conveyor")) {
    toml::table o;
    TableReader r(ctx, subtable(ctx, root, "conveyor", empty), scene_section("conveyor"), "conveyor", o);
    ConveyorSpec c;
    c.material = material_index(r, s.materials);
    c.speed = r.number("speed");
    c.ground = r.number("ground");
    c.depth = r.number("depth");
    c.z_min = r.number("z_min");
    c.z_max = r.number("z_max");
    if (!(c.z_max > c.z_min)) r.fail("z_max", "must exceed z_min");
    const double margin = 4 * s.config.dx;  // 4 cells: outside every shape function's reach of a wall
    const auto inflow = r.optional_number("inflow"), outflow = r.optional_number("outflow");
    c.inflow = inflow ? *inflow : s.config.domain_max[0] - margin;
    c.outflow = outflow ? *outflow : s.config.domain_min[0] + margin;
    o.insert_or_assign("inflow", c.inflow);
    o.insert_or_assign("outflow", c.outflow);
    if (!(c.inflow > c.outflow)) r.fail("inflow", "must exceed outflow");
    if (c.inflow > s.config.domain_max[0] - margin || c.outflow < s.config.domain_min[0] + margin)
      r.fail(inflow ? "inflow" : "outflow", "must lie at least 4 cells inside the domain");
    if (c.ground - margin < s.config.domain_min[1] || c.ground + c.depth > s.config.domain_max[1] - margin ||
        c.z_min < s.config.domain_min[2] + margin || c.z_max > s.config.domain_max[2] - margin)
      r.fail("ground", "the snow bed must lie at least 4 cells inside the domain");
    c.boundary = WallType(r.choice_index("boundary") + 1);
    c.friction = r.number("friction");
    r.finish();
    s.conveyor = c;
    out.insert("conveyor", std::move(o));
  }
  if (s.tire && s.tire->free_spin) s.tire->speed = s.conveyor ? s.conveyor->speed : 0;  // rolling with the ground
  // [[loads]]
  if (const toml::array* a = table_array("loads")) {
    toml::array o;
    for (std::size_t i = 0; i < a->size(); ++i) {
      toml::table lo;
      TableReader r(ctx, *a->get(i)->as_table(), scene_section("loads"), "loads." + std::to_string(i), lo);
      LoadSpec l;
      l.region_min = r.vec3("region_min");
      l.region_max = r.vec3("region_max");
      r.require_above("region_max", l.region_max, "region_min", l.region_min);
      l.force = r.vec3("force");
      l.ramp_time = r.number("ramp_time");
      r.finish();
      s.loads.push_back(l);
      o.push_back(std::move(lo));
    }
    out.insert("loads", std::move(o));
  }
  // [contact], [metrics], [output], [render]
  {
    toml::table mo, oo, ro;
    {
      toml::table co;
      TableReader c(ctx, subtable(ctx, root, "contact", empty), scene_section("contact"), "contact", co);
      s.contact_friction = read_friction(c);
      if (root.contains("contact") && s.tire && s.tire->rubber)  // one friction joins the two contact groups
        c.fail("friction", "is the rubber tire's: its contact takes [tire] friction_law and friction; remove [contact]");
      c.finish();
      out.insert("contact", std::move(co));
    }
    TableReader m(ctx, subtable(ctx, root, "metrics", empty), scene_section("metrics"), "metrics", mo);
    s.metrics.displaced_distance = m.number("displaced_distance");
    s.metrics.footprint = m.boolean("footprint");
    if (s.metrics.footprint && s.tire && s.tire->contact == ColliderContact::penalty) {
      if (m.has("footprint"))
        m.fail("footprint", "is summed at the grid nodes the tire holds, and a tire with contact = \"penalty\" holds "
                            "none: set footprint = false");
      s.metrics.footprint = false;  // the default follows the contact
      mo.insert_or_assign("footprint", false);
    }
    s.metrics.fragments = m.boolean("fragments");
    s.metrics.fragment_link_cells = m.number("fragment_link_cells");
    s.metrics.fragment_min_particles = int(m.integer("fragment_min_particles"));
    m.finish();
    out.insert("metrics", std::move(mo));
    TableReader o(ctx, subtable(ctx, root, "output", empty), scene_section("output"), "output", oo);
    s.output.particles = o.boolean("particles");
    o.finish();
    out.insert("output", std::move(oo));
    TableReader r(ctx, subtable(ctx, root, "render", empty), scene_section("render"), "render", ro);
    s.render.style = r.choice("style");
    s.render.color_by = r.choice("color_by");
    s.render.width = int(r.integer("width"));
    s.render.height = int(r.integer("height"));
    s.render.fps = int(r.integer("fps"));
    s.render.color_map = r.choice("color_map");
    s.render.color_min = r.optional_number("color_min");
    s.render.color_max = r.optional_number("color_max");
    if (s.render.color_min && s.render.color_max && !(*s.render.color_max > *s.render.color_min))
      r.fail("color_max", "must exceed color_min");
    s.render.camera = r.choice("camera");
    s.render.camera_follow = r.boolean("camera_follow");
    s.render.camera_position = r.optional_vec3("camera_position");
    s.render.camera_target = r.optional_vec3("camera_target");
    s.render.fov = r.number("fov");
    s.render.light_direction = r.optional_vec3("light_direction");
    if (s.render.light_direction == Point{0, 0, 0}) r.fail("light_direction", "must not be zero");
    s.render.shadows = r.boolean("shadows");
    s.render.ambient_occlusion = r.boolean("ambient_occlusion");
    s.render.ground = r.boolean("ground");
    s.render.ground_height = r.optional_number("ground_height");
    s.render.legend = r.boolean("legend");
    s.render.cutaway = r.boolean("cutaway");
    s.render.sphere_scale = r.number("sphere_scale");
    s.render.subsurface = r.boolean("subsurface");
    s.render.snow_grain = r.number("snow_grain");
    r.finish();
    out.insert("render", std::move(ro));
  }

  std::ostringstream text;
  text << "# " << s.name << ": resolved by firn from " << path
       << " (every default and override filled in, SI units); run it as is to reproduce the run.\n"
       << out << "\n";
  loaded.resolved_toml = text.str();
  return loaded;
}

}  // namespace

LoadedScene load_scene(const std::string& path, const SceneOptions& options) {
  try {
    return read_scene(path, toml::parse_file(path), options);
  } catch (const toml::parse_error& e) {
    throw syntax_error(path, e);
  }
}

LoadedScene load_scene_text(const std::string& text, const std::string& path, const SceneOptions& options) {
  try {
    return read_scene(path, toml::parse(text, path), options);
  } catch (const toml::parse_error& e) {
    throw syntax_error(path, e);
  }
}

}  // namespace firn
