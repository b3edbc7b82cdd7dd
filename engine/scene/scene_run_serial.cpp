#include "engine/scene/scene_run_backends.hpp"
#include "engine/scene/scene_run_impl.hpp"
#include "kernels/backend/serial.hpp"

namespace firn {

RunSummary run_scene_serial(const LoadedScene& scene, const RunOptions& options) {
  return scene_run_detail::run_on(scene, options, backend::Serial{});
}

}  // namespace firn
