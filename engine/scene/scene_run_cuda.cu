// The whole step instantiated for the CUDA backend (every scene feature: materials, colliders,
// loads, the conveyor, metrics), so that a build with nvcc compiles every kernel as device code.
#include <type_traits>

#include "engine/scene/scene_run_backends.hpp"
#include "engine/scene/scene_run_impl.hpp"
#include "kernels/backend/cuda.hpp"

namespace firn {

static_assert(std::is_trivially_copyable_v<ParticleView<float>> && std::is_trivially_copyable_v<BinningView> &&
                  std::is_trivially_copyable_v<SparseGridView<float>> &&
                  std::is_trivially_copyable_v<GridSlotsView<float>>,
              "kernels take views by value");
static_assert(std::is_trivially_copyable_v<P2GScatter<float, QuadraticBSpline<float>, Transfer::apic>> &&
                  std::is_trivially_copyable_v<G2PGather<float, QuadraticBSpline<float>, Transfer::apic>> &&
                  std::is_trivially_copyable_v<GridUpdateSlots<float, Transfer::apic>>,
              "the step's functors are copied into kernels");

RunSummary run_scene_cuda(const LoadedScene& scene, const RunOptions& options) {
  return scene_run_detail::run_on(scene, options, backend::Cuda{});
}

}  // namespace firn
