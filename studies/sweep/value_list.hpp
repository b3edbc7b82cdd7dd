// `--vary KEY=V1,V2,...` (DESIGN.md section 5): the list of values one scene key takes in a sweep.
// Each value is passed on as `--set KEY=VALUE`, so it is read exactly like a `--set` value (a TOML
// value, or a plain string where it is not one).
#pragma once

#include <string>
#include <vector>

namespace firn::sweep {

// Splits "V1,V2,..." on the commas that are outside brackets ([], {}) and quotes ('', ""), and
// trims the spaces around each value: "[0,0,1],[0,0,2]" gives "[0,0,1]" and "[0,0,2]", and
// "5 mph, 10 mph" gives "5 mph" and "10 mph". Throws std::invalid_argument on an empty value, an
// unclosed quote or an unbalanced bracket.
std::vector<std::string> split_value_list(const std::string& list);

struct VariedKey {
  std::string key;                  // as given, e.g. "tire.tread"
  std::vector<std::string> values;  // as given, trimmed
};

// Reads "KEY=V1,V2,..."; throws std::invalid_argument naming the argument when it is malformed.
VariedKey parse_vary(const std::string& argument);

}  // namespace firn::sweep
