#include "studies/sweep/combinations.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace firn::sweep {

std::vector<std::vector<std::string>> cartesian_product(const std::vector<VariedKey>& keys) {
  std::vector<std::vector<std::string>> combinations{{}};
  for (const VariedKey& key : keys) {
    std::vector<std::vector<std::string>> longer;
    for (const auto& prefix : combinations)
      for (const std::string& value : key.values) {
        longer.push_back(prefix);
        longer.back().push_back(value);
      }
    combinations = std::move(longer);
  }
  return combinations;
}

std::vector<std::string> set_arguments(const std::vector<VariedKey>& keys, const std::vector<std::string>& values) {
  std::vector<std::string> sets;
  for (std::size_t i = 0; i < keys.size(); ++i) sets.push_back(keys[i].key + "=" + values.at(i));
  return sets;
}

std::string run_name(std::size_t number, std::size_t total, const std::vector<std::string>& values) {
  const int digits = std::max<int>(3, int(std::to_string(total).size()));
  char prefix[32];
  std::snprintf(prefix, sizeof prefix, "%0*zu", digits, number);
  std::string name = prefix;
  for (const std::string& value : values) {
    std::string slug;
    for (const char c : value) {
      const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '+';
      if (keep)
        slug += c;
      else if (!slug.empty() && slug.back() != '-')
        slug += '-';
    }
    while (!slug.empty() && (slug.back() == '-' || slug.back() == '.')) slug.pop_back();
    if (slug.size() > 40) slug.resize(40);
    if (!slug.empty()) name += "_" + slug;
  }
  return name;
}

}  // namespace firn::sweep
