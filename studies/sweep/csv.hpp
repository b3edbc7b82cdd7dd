// The CSV dialect of firn's tables (RFC 4180): fields separated by commas, a field that holds a
// comma, a quote or a line break quoted with '"' and its quotes doubled; numbers printed with %.6g.
#pragma once

#include <string>
#include <vector>

namespace firn::sweep {

std::string csv_field(const std::string& text);
std::vector<std::string> split_csv_line(const std::string& line);  // the inverse of csv_field per field
std::string csv_number(double value);                              // %.6g
std::string formatted(const char* printf_format, double value);     // one number, e.g. "%.2f"

}  // namespace firn::sweep
