// run_scene on the serial and CUDA backends, each compiled in its own translation unit
// (scene_run_serial.cpp, scene_run_cuda.cu or, without FIRN_CUDA, engine/cuda_absent.cpp).
#pragma once

#include "engine/output/run_summary.hpp"
#include "engine/scene/scene_reader.hpp"
#include "engine/scene/scene_run.hpp"

namespace firn {

RunSummary run_scene_serial(const LoadedScene& scene, const RunOptions& options);
RunSummary run_scene_cuda(const LoadedScene& scene, const RunOptions& options);

}  // namespace firn
