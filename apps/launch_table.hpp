// The launch table that --profile prints (firn run, firn bench step): each launch's time and
// count per step, costliest first, then the loop's time outside launches (host work).
#pragma once

#include <map>
#include <string>

#include "kernels/backend/launch_profile.hpp"

namespace firn::app {

void print_launch_table(const std::map<std::string, backend::LaunchProfile::Entry>& launches, double loop_seconds,
                        long steps);

}  // namespace firn::app
