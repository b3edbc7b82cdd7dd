// A run's metrics.csv (DESIGN.md section 5) read back: the 12 standard columns
// frame,step,time,dt,particles,kinetic_energy,elastic_energy,momentum_x,momentum_y,momentum_z,
// max_speed,min_J, then the energy budget and the scene's own metric columns, whatever they are named.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace firn::sweep {

inline constexpr std::size_t standard_metrics_columns = 12;

struct MetricsHistory {
  std::vector<std::string> columns;       // the header
  std::vector<std::vector<double>> rows;  // one per frame; NaN where a cell is empty or not a number

  // The columns after the standard ones, in file order.
  std::vector<std::string> scene_columns() const;
  // The column's values at every frame after frame 0 (the first row), NaN cells left out.
  std::optional<double> mean_after_first_frame(const std::string& column) const;
  // The column's value at the first frame whose time is >= time - 1e-9; none if the run never got
  // there (or the cell is empty).
  std::optional<double> value_at(const std::string& column, double time) const;

  // The index of a column, or -1.
  int column_index(const std::string& column) const;
};

// Parses the text of a metrics.csv. A row shorter than the header has NaN in its missing cells.
// Throws std::runtime_error when there is no header or the header has no `time` column.
MetricsHistory parse_metrics_csv(const std::string& text);

}  // namespace firn::sweep
