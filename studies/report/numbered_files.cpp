#include "studies/report/numbered_files.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace firn::report {

std::vector<std::string> numbered_files(const std::string& dir, const std::string& sub, const std::string& ext) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir + "/" + sub, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= ext.size() || name.compare(name.size() - ext.size(), ext.size(), ext) != 0) continue;
    const std::string stem = name.substr(0, name.size() - ext.size());
    if (std::all_of(stem.begin(), stem.end(), [](unsigned char c) { return std::isdigit(c); }))
      names.push_back(sub + "/" + name);
  }
  // Zero-padded numbers of equal width sort as numbers; a wider one (frame 100000) sorts after.
  std::sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
    return a.size() != b.size() ? a.size() < b.size() : a < b;
  });
  return names;
}

std::vector<std::string> evenly_spaced(const std::vector<std::string>& items, std::size_t count) {
  if (items.size() <= count) return items;
  std::vector<std::string> picked;
  if (count == 0) return picked;
  if (count == 1) return {items.back()};
  for (std::size_t i = 0; i < count; ++i) picked.push_back(items[i * (items.size() - 1) / (count - 1)]);
  return picked;
}

int frame_number(const std::string& name) {
  const std::size_t slash = name.find_last_of('/');
  return std::atoi(name.c_str() + (slash == std::string::npos ? 0 : slash + 1));
}

}  // namespace firn::report
