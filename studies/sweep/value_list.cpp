#include "studies/sweep/value_list.hpp"

#include <stdexcept>

namespace firn::sweep {
namespace {

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

}  // namespace

std::vector<std::string> split_value_list(const std::string& list) {
  std::vector<std::string> values;
  std::string closers;  // the brackets still open, innermost last
  char quote = 0;
  std::string current;
  auto finish = [&] {
    std::string v = trimmed(current);
    if (v.empty()) throw std::invalid_argument("empty value in the list '" + list + "'");
    values.push_back(std::move(v));
    current.clear();
  };
  for (std::size_t i = 0; i < list.size(); ++i) {
    const char c = list[i];
    if (quote) {
      if (c == '\\' && quote == '"' && i + 1 < list.size()) {
        current += c;
        current += list[++i];
        continue;
      }
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '[' || c == '{') {
      closers += c == '[' ? ']' : '}';
    } else if (c == ']' || c == '}') {
      if (closers.empty() || closers.back() != c)
        throw std::invalid_argument(std::string("unbalanced '") + c + "' in the list '" + list + "'");
      closers.pop_back();
    } else if (c == ',' && closers.empty()) {
      finish();
      continue;
    }
    current += c;
  }
  if (quote) throw std::invalid_argument(std::string("unclosed ") + quote + " in the list '" + list + "'");
  if (!closers.empty())
    throw std::invalid_argument(std::string("missing '") + closers.back() + "' in the list '" + list + "'");
  finish();
  return values;
}

VariedKey parse_vary(const std::string& argument) {
  const auto eq = argument.find('=');
  if (eq == std::string::npos || trimmed(argument.substr(0, eq)).empty())
    throw std::invalid_argument("--vary " + argument + ": expected KEY=V1,V2,..., e.g. simulation.dx=0.02,0.01");
  try {
    return {trimmed(argument.substr(0, eq)), split_value_list(argument.substr(eq + 1))};
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("--vary " + argument + ": " + e.what());
  }
}

}  // namespace firn::sweep
