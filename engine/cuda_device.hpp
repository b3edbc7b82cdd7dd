// Whether the CUDA backend can run: defined by engine/cuda_device.cu in FIRN_CUDA builds and by
// engine/cuda_absent.cpp otherwise, so that code compiled by the C++ compiler alone can ask.
#pragma once

#include <string>

namespace firn {

// An empty string when the CUDA backend can run here, else the one line that says why not.
std::string cuda_unavailable_reason();

}  // namespace firn
