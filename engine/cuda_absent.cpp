// A build without FIRN_CUDA (no nvcc): the CUDA backend's entry points say it is absent.
#include <stdexcept>

#include "engine/cuda_device.hpp"
#include "engine/scene/scene_run_backends.hpp"

namespace firn {

namespace {
const char* const kNoCuda = "this build has no CUDA backend";
}

std::string cuda_unavailable_reason() { return kNoCuda; }

RunSummary run_scene_cuda(const LoadedScene&, const RunOptions&) { throw std::runtime_error(kNoCuda); }

}  // namespace firn
