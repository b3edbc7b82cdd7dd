// The thesis' Table 5.1 for a sweep: "total amount of snow particles displaced after 20 time steps
// (10 ms)", one row per tread, one column per snow and their ratio; here for any metric of
// sweep.csv and any varied keys, read from sweep.csv.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "studies/report/html_writer.hpp"

namespace firn::report {

// A CSV file read back (studies/sweep/csv.hpp's dialect, one record a line): the first line is the
// header. Lines shorter than the header are padded with empty cells.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};
CsvTable parse_csv(const std::string& text);

// The columns of sweep.csv before `status`: its varied keys.
std::size_t varied_key_columns(const CsvTable& sweep);

// The pivot of sweep.csv's columns of scene metric `metric` (C@T for each --at time T, mean_C) by
// the varied keys: one row per combination of the keys after the first, and under each of those
// columns one column per value of the first key (the snow, in the thesis' 18-run matrix), followed
// by their ratio (second / first, the caption says which) when the first key has two values. Empty (no rows) when
// sweep.csv has no column of the metric.
HtmlTable pivot_table(const CsvTable& sweep, const std::string& metric);

}  // namespace firn::report
