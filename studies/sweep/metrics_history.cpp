#include "studies/sweep/metrics_history.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "studies/sweep/csv.hpp"

namespace firn::sweep {
namespace {

double cell_value(const std::string& cell) {
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  return cell.empty() || *end ? std::numeric_limits<double>::quiet_NaN() : v;
}

}  // namespace

int MetricsHistory::column_index(const std::string& column) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == column) return int(i);
  return -1;
}

std::vector<std::string> MetricsHistory::scene_columns() const {
  if (columns.size() <= standard_metrics_columns) return {};
  return {columns.begin() + standard_metrics_columns, columns.end()};
}

std::optional<double> MetricsHistory::mean_after_first_frame(const std::string& column) const {
  const int c = column_index(column);
  if (c < 0) return std::nullopt;
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t r = 1; r < rows.size(); ++r)
    if (!std::isnan(rows[r][c])) sum += rows[r][c], ++n;
  if (n == 0) return std::nullopt;
  return sum / double(n);
}

std::optional<double> MetricsHistory::value_at(const std::string& column, double time) const {
  const int c = column_index(column), t = column_index("time");
  if (c < 0) return std::nullopt;
  for (const auto& row : rows)
    if (row[t] >= time - 1e-9) {
      if (std::isnan(row[c])) return std::nullopt;
      return row[c];
    }
  return std::nullopt;
}

MetricsHistory parse_metrics_csv(const std::string& text) {
  MetricsHistory h;
  std::istringstream lines(text);
  std::string line;
  if (!std::getline(lines, line) || line.empty()) throw std::runtime_error("metrics.csv has no header");
  h.columns = split_csv_line(line);
  if (h.column_index("time") < 0) throw std::runtime_error("metrics.csv has no time column");
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> cells = split_csv_line(line);
    std::vector<double> row(h.columns.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < row.size() && i < cells.size(); ++i) row[i] = cell_value(cells[i]);
    h.rows.push_back(std::move(row));
  }
  return h;
}

}  // namespace firn::sweep
