#include "studies/report/scene_parameters.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "studies/report/html_writer.hpp"
#include "studies/sweep/csv.hpp"

namespace firn::report {
namespace {

// Numbers as sweep.csv prints them (toml++ writes 0.004 as 0.0040000000000000001).
std::string value_text(const toml::node& node) {
  if (const auto* s = node.as_string()) return s->get();
  if (const auto* d = node.as_floating_point()) return sweep::csv_number(d->get());
  if (const auto* a = node.as_array()) {
    std::string text = "[";
    for (std::size_t i = 0; i < a->size(); ++i) text += (i ? ", " : "") + value_text(*a->get(i));
    return text + "]";
  }
  std::ostringstream out;
  node.visit([&out](const auto& v) { out << v; });
  return out.str();
}

// A table's keys and values, one row each, keys in alphabetical order (toml++ keeps no other).
std::string key_value_table(const std::string& caption, const toml::table& table) {
  HtmlTable t;
  t.caption = caption;
  t.header = {"key", "value"};
  for (const auto& [key, value] : table) t.rows.push_back({std::string(key.str()), value_text(value)});
  return html_table(t);
}

// An array of tables ([[bodies]]): one row each, a column for every key any of them has.
std::string array_table(const std::string& caption, const toml::array& array) {
  HtmlTable t;
  t.caption = caption;
  for (const auto& element : array)
    if (const auto* table = element.as_table())
      for (const auto& [key, value] : *table)
        if (std::find(t.header.begin(), t.header.end(), key.str()) == t.header.end()) t.header.emplace_back(key.str());
  for (const auto& element : array)
    if (const auto* table = element.as_table()) {
      std::vector<std::string> row;
      for (const std::string& key : t.header) {
        const toml::node* value = table->get(key);
        row.push_back(value ? value_text(*value) : "");
      }
      t.rows.push_back(std::move(row));
    }
  return html_table(t);
}

}  // namespace

std::string scene_parameters_html(const std::string& resolved_toml) {
  toml::table scene;
  try {
    scene = toml::parse(resolved_toml);
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(std::string("scene.resolved.toml: ") + std::string(e.description()));
  }
  std::string html;
  if (const auto* simulation = scene["simulation"].as_table()) html += key_value_table("[simulation]", *simulation);
  if (const auto* materials = scene["materials"].as_table())
    for (const auto& [name, material] : *materials)
      if (const auto* m = material.as_table()) html += key_value_table("[materials." + std::string(name.str()) + "]", *m);
  for (const char* section : {"bodies", "colliders"})
    if (const auto* array = scene[section].as_array()) html += array_table(std::string("[[") + section + "]]", *array);
  for (const char* section : {"tire", "conveyor"})
    if (const auto* table = scene[section].as_table()) html += key_value_table(std::string("[") + section + "]", *table);
  return html;
}

}  // namespace firn::report
