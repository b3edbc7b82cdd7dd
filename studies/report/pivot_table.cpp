#include "studies/report/pivot_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "studies/sweep/csv.hpp"

namespace firn::report {
namespace {

// The value of `text` as a number; NaN when it is not one.
double number(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return text.empty() || *end ? std::nan("") : v;
}

std::size_t index_of(std::vector<std::string>& list, const std::string& item) {
  const auto at = std::find(list.begin(), list.end(), item);
  if (at != list.end()) return std::size_t(at - list.begin());
  list.push_back(item);
  return list.size() - 1;
}

}  // namespace

CsvTable parse_csv(const std::string& text) {
  CsvTable table;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    std::vector<std::string> cells = sweep::split_csv_line(line);
    if (table.header.empty()) {
      table.header = std::move(cells);
      continue;
    }
    cells.resize(std::max(cells.size(), table.header.size()));
    table.rows.push_back(std::move(cells));
  }
  return table;
}

std::size_t varied_key_columns(const CsvTable& sweep) {
  return std::size_t(std::find(sweep.header.begin(), sweep.header.end(), "status") - sweep.header.begin());
}

HtmlTable pivot_table(const CsvTable& sweep, const std::string& metric) {
  const std::size_t keys = varied_key_columns(sweep);
  HtmlTable table;
  std::vector<std::size_t> columns;  // sweep.csv's columns of the metric
  for (std::size_t c = keys; c < sweep.header.size(); ++c)
    if (sweep.header[c] == "mean_" + metric || sweep.header[c].rfind(metric + "@", 0) == 0) columns.push_back(c);
  if (keys == 0 || keys == sweep.header.size() || columns.empty()) return table;
  // The first key's values (the pivot's columns) and the other keys' combinations (its rows), in
  // the order sweep.csv lists them.
  std::vector<std::string> firsts, others;
  std::vector<std::pair<std::size_t, std::size_t>> at;  // (row, first-key column) of each sweep.csv row
  for (const auto& row : sweep.rows) {
    std::string other;
    for (std::size_t k = 1; k < keys; ++k) other += (k > 1 ? ", " : "") + row[k];
    at.emplace_back(index_of(others, other), index_of(firsts, row[0]));
  }
  const bool ratio = firsts.size() == 2;
  const std::size_t width = firsts.size() + (ratio ? 1 : 0);
  std::string row_keys;
  for (std::size_t k = 1; k < keys; ++k) row_keys += (k > 1 ? ", " : "") + sweep.header[k];
  table.caption = metric + " by " + (keys > 1 ? row_keys + " (rows) and " : "") + sweep.header[0] + " (columns)" +
                  (ratio ? "; ratio: " + firsts[1] + " / " + firsts[0] : "");
  table.header.push_back(row_keys);
  table.groups.emplace_back("", 1);
  for (const std::size_t c : columns) {
    table.groups.emplace_back(sweep.header[c], int(width));
    for (const std::string& f : firsts) table.header.push_back(f);
    if (ratio) table.header.push_back("ratio");
  }
  table.rows.assign(others.size(), std::vector<std::string>(1 + columns.size() * width));
  for (std::size_t r = 0; r < others.size(); ++r) table.rows[r][0] = others[r].empty() ? "all runs" : others[r];
  for (std::size_t i = 0; i < sweep.rows.size(); ++i)
    for (std::size_t g = 0; g < columns.size(); ++g)
      table.rows[at[i].first][1 + g * width + at[i].second] = sweep.rows[i][columns[g]];
  if (ratio)
    for (auto& row : table.rows)
      for (std::size_t g = 0; g < columns.size(); ++g) {
        const double a = number(row[1 + g * width]), b = number(row[2 + g * width]);
        if (std::isfinite(a) && std::isfinite(b) && a != 0) row[3 + g * width] = sweep::formatted("%.3g", b / a);
      }
  return table;
}

}  // namespace firn::report
