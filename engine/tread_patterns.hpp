// The tread patterns of the thesis' tire experiment (section 4.3.2, Figure 4.8), drawn as blocks on
// one pitch of the unrolled tread for kernels/tire_shape.hpp (u: circumferential, in pitch lengths;
// w: lateral, in tire widths, -1/2..1/2). A tire rolling forward turns so that the tread at the
// ground moves backward: the edge of a block at larger u meets the snow first.
#pragma once

#include <string>
#include <vector>

#include "kernels/tire_shape.hpp"

namespace firn {

struct TreadPattern {
  std::string name;
  std::string doc;
  std::vector<TreadBlock<double>> blocks;
};

const std::vector<TreadPattern>& tread_patterns();
const TreadPattern* find_tread_pattern(const std::string& name);

// A tire of the given dimensions carrying the named pattern (throws std::invalid_argument for an
// unknown name).
TireShape<double> make_tire_shape(const std::string& pattern, double radius, double width, double tread_depth,
                                  int pitches);

}  // namespace firn
