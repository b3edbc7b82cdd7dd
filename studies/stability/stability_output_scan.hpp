// Scans a run's output folder for non-finite numbers: every cell of metrics.csv (text, "%.9g",
// so a NaN or Inf prints as "nan", "inf", "-inf") and every Float32/Float64 array of every
// particles/NNNNN.vtp (VTK XML, "appended raw" binary with UInt64 byte-count headers, as
// engine/output/vtp_writer.cpp writes it).
#pragma once

#include <string>
#include <vector>

namespace firn::study {

// One line per file with a non-finite value (or that cannot be read as written), naming the file
// and the first column or array where it was found; empty when every number is finite.
std::vector<std::string> non_finite_outputs(const std::string& run_dir);

// The same for one file's text: metrics.csv, and one .vtp file.
std::string non_finite_in_csv(const std::string& text);  // "" or "column C, row R"
std::string non_finite_in_vtp(const std::string& bytes);  // "" or "array NAME" or "malformed: ..."

}  // namespace firn::study
