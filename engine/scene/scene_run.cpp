#include "engine/scene/scene_run.hpp"

#include "engine/scene/scene_run_backends.hpp"
#include "engine/scene/scene_run_impl.hpp"
#include "kernels/backend/openmp.hpp"

namespace firn {

RunSummary run_scene(const LoadedScene& scene, const RunOptions& options) {
  switch (options.backend) {
    case BackendKind::serial: return run_scene_serial(scene, options);
    case BackendKind::cuda: return run_scene_cuda(scene, options);
    case BackendKind::openmp: break;
  }
  return scene_run_detail::run_on(scene, options, backend::OpenMP(options.threads));
}

}  // namespace firn
