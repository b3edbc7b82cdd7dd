// A run's numbered outputs (DESIGN.md section 5: frames/NNNNN.png, footprint/NNNNN.png), and the
// few of them a report shows.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace firn::report {

// The names "SUB/NNNNN.EXT" (relative to `dir`) of the files in DIR/SUB whose name is digits and
// then `ext` (e.g. ".png"), in frame order; none when the folder is absent.
std::vector<std::string> numbered_files(const std::string& dir, const std::string& sub, const std::string& ext);

// `count` of `items` evenly spaced from the first to the last, both included (all of them when
// there are no more than `count`).
std::vector<std::string> evenly_spaced(const std::vector<std::string>& items, std::size_t count);

// The frame number of a name from numbered_files ("frames/00012.png": 12).
int frame_number(const std::string& name);

}  // namespace firn::report
