// Output frames are files named by their frame number in five digits: particles/00042.vtp,
// footprint/00042.csv, frames/00042.png.
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>

namespace firn {

inline std::string frame_name(int frame) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%05d", frame);
  return buf;
}

// The frame number of a particle frame's file name (NNNNN.vtp), or -1 for any other name.
inline int particle_frame_number(const std::string& name) {
  const bool frame = name.size() == 9 && name.compare(5, 4, ".vtp") == 0 &&
                     std::all_of(name.begin(), name.begin() + 5, [](char c) { return c >= '0' && c <= '9'; });
  return frame ? std::stoi(name.substr(0, 5)) : -1;
}

}  // namespace firn
