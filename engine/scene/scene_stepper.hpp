// The step loop of a scene, written once: a SceneStepper builds and owns the Simulation of a scene
// (build_scene) and its conveyor, and steps both toward a target time. `firn run`
// (scene_run_impl.hpp), the stability study's probe and the tests step scenes through it. All the
// loop's state (simulation, conveyor) lives here.
//
//   SceneStepper<float, backend::OpenMP> stepper(scene, backend::OpenMP(threads));
//   while (stepper.before(t)) stepper.step_toward(t);
#pragma once

#include <algorithm>
#include <functional>
#include <optional>
#include <sstream>

#include "engine/scene/conveyor.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/scene_builder.hpp"
#include "engine/simulation.hpp"
#include "engine/stability_guard.hpp"
#include "engine/state_stream.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn {

template <class T, class Backend>
struct SceneStepperOptions {
  bool rest_positions = false;  // keep x0, the rest positions (enabled before the scene is built)
  // Called once the scene is built, before the simulation is prepared: to enable what the caller
  // measures (the footprint map, the energy budget).
  std::function<void(Simulation<T, Backend>&, const BuiltScene&, const Conveyor*)> before_prepare;
};

template <class T, class Backend>
class SceneStepper {
 public:
  // Throws SceneError (a body without particles) or std::invalid_argument (a bad configuration).
  SceneStepper(const SceneSpec& scene, const Backend& backend, const SceneStepperOptions<T, Backend>& options = {})
      : sim_(scene.config, backend) {
    if (options.rest_positions) sim_.enable(Attribute::x0);
    built_ = build_scene(scene, sim_);
    if (scene.conveyor) conveyor_.emplace(scene, *scene.conveyor);
    if (options.before_prepare) options.before_prepare(sim_, built_, conveyor());
    sim_.prepare();
  }
  // The conveyor's address is handed out (conveyor(), before_prepare): a stepper stays where it is.
  SceneStepper(const SceneStepper&) = delete;
  SceneStepper& operator=(const SceneStepper&) = delete;

  // Whether the simulation is still short of `target`, to a relative 1e-12, so that rounding in
  // the accumulated time never asks for a sliver of a step.
  bool before(double target) const { return sim_.time() < target * (1 - 1e-12); }

  // One step toward `target`: the conveyor brings the bed up to the current time, then the
  // simulation steps by its next time step, cut short so as not to pass `target`. Throws
  // StabilityError for a guard stop.
  void step_toward(double target) {
    if (conveyor_) conveyor_->update(sim_, sim_.time());
    sim_.step(std::min(sim_.next_dt(), target - sim_.time()));
    if (conveyor_ && built_.tire >= 0) check_tire_above_ground();
  }

  // The loop's state for a checkpoint (engine/scene/checkpoint.hpp): the simulation's, then the
  // conveyor's. load_state throws CheckpointError for a state that is not of this scene.
  void save_state(StateWriter& out) {
    sim_.save_state(out);
    if (conveyor_) conveyor_->save_state(out);
  }
  void load_state(StateReader& in) {
    sim_.load_state(in);
    if (conveyor_) conveyor_->load_state(in);
    StateReader::expect(in.at_end(), "checkpoint's conveyor differs from the scene's");
  }

  Simulation<T, Backend>& sim() { return sim_; }
  const Simulation<T, Backend>& sim() const { return sim_; }
  const BuiltScene& built() const { return built_; }
  const Conveyor* conveyor() const { return conveyor_ ? &*conveyor_ : nullptr; }  // null without one

 private:
  // Colliders do not touch each other: a loaded axle whose snow does not carry its load would fall
  // through the conveyor's ground, so the run stops once the tread's lowest point is more than a
  // cell below it (a cell of snow squeezed under the tread may still push it back up).
  void check_tire_above_ground() const {
    const ColliderBody& tire = sim_.collider(built_.tire);
    const double bottom = tire.collider.center[1] - tire.collider.tire.radius, ground = conveyor_->spec().ground;
    if (tire.motion != ColliderBody::Motion::loaded_axle || bottom >= ground - sim_.config().dx) return;
    std::ostringstream msg;
    msg << "tire guard: step " << sim_.steps() << ", t = " << sim_.time() << " s: the loaded tire's lowest point (y = "
        << bottom << " m) went through the ground (y = " << ground << " m): the snow does not carry the load";
    throw StabilityError(msg.str());
  }

  Simulation<T, Backend> sim_;
  BuiltScene built_;
  std::optional<Conveyor> conveyor_;
};

}  // namespace firn
