// The runs of a sweep: the Cartesian product of the `--vary` lists, and the name of each run's
// output folder.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "studies/sweep/value_list.hpp"

namespace firn::sweep {

// Every combination of one value per key, in order, the first key varying slowest: for
// a=1,2 and b=x,y: (1,x) (1,y) (2,x) (2,y). Each combination holds one value per key.
std::vector<std::vector<std::string>> cartesian_product(const std::vector<VariedKey>& keys);

// "KEY=VALUE" for each key, as given to `firn run --set`.
std::vector<std::string> set_arguments(const std::vector<VariedKey>& keys, const std::vector<std::string>& values);

// The folder name of run `number` (1-based) of `total`: the number zero-padded to at least three
// digits, then the values made safe for a file name and joined with '_', e.g.
// "003_bowtie_5-mph" or "001_0-0-1". Distinct numbers make distinct names.
std::string run_name(std::size_t number, std::size_t total, const std::vector<std::string>& values);

}  // namespace firn::sweep
