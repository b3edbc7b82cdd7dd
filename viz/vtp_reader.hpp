// Reads the particle files that engine/output/vtp_writer writes (VTK XML PolyData, appended raw
// binary with UInt64 block headers), without VTK: the XML header names each array's type,
// components and offset into the appended block.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace firn::viz {

struct VtpArrayData {
  int components = 1;
  std::vector<double> values;  // point-major: values[point * components + component]
};

struct VtpFile {
  std::size_t points = 0;
  VtpArrayData positions;
  std::map<std::string, VtpArrayData> arrays;  // point data by name
};

// Throws std::runtime_error naming the file on anything it cannot read.
VtpFile read_vtp(const std::string& path);

}  // namespace firn::viz
