// Simulation and conveyor state saved between two steps and loaded into a simulation built
// afresh from the same scene continue bit for bit as the uninterrupted run (engine/simulation.hpp,
// save_state and load_state), with every piece of state that a later step reads: particles in
// memory order after conveyor injection and removal, a loaded axle's motion and reactions, a free
// spin, the footprint, loads' ramps, plastic state and the energy budget.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/scene/scene_reader.hpp"
#include "engine/scene/scene_stepper.hpp"
#include "kernels/backend/openmp.hpp"

namespace firn {
namespace {

SceneSpec scene(const std::string& file, std::vector<std::string> overrides) {
  SceneOptions o;
  o.overrides = std::move(overrides);
  return load_scene(std::string(FIRN_SOURCE_DIR) + "/scenes/" + file, o).spec;
}

// A scene stepped as firn run steps it (engine/scene/scene_stepper.hpp), with its footprint and
// energy budget on.
struct SteppedScene {
  SceneStepper<float, backend::OpenMP> stepper;
  Simulation<float, backend::OpenMP>& sim;
  SteppedScene(const SceneSpec& s, int threads) : stepper(s, backend::OpenMP(threads), measured()), sim(stepper.sim()) {}
  void steps(int n) {
    for (int i = 0; i < n; ++i) stepper.step_toward(1e9);
  }
  std::string save() {
    StateWriter out;
    stepper.save_state(out);
    return out.bytes();
  }
  void load(const std::string& bytes) {
    StateReader in(bytes);
    stepper.load_state(in);
  }
  static SceneStepperOptions<float, backend::OpenMP> measured() {
    SceneStepperOptions<float, backend::OpenMP> o;
    o.before_prepare = [](Simulation<float, backend::OpenMP>& sim, const BuiltScene& built, const Conveyor*) {
      if (built.tire >= 0) sim.enable_footprint(built.tire);
      sim.enable_energy_budget();
    };
    return o;
  }
};

void expect_resume_matches(const SceneSpec& s, int before, int after) {
  SteppedScene whole(s, 2);
  whole.steps(before);
  const std::string saved = whole.save();
  whole.steps(after);

  SteppedScene resumed(s, 1);  // another thread count: the state, not the schedule, decides the result
  resumed.load(saved);
  resumed.steps(after);

  EXPECT_EQ(resumed.sim.steps(), whole.sim.steps());
  EXPECT_EQ(resumed.sim.time(), whole.sim.time());
  EXPECT_EQ(resumed.sim.particle_count(), whole.sim.particle_count());
  EXPECT_EQ(resumed.sim.state_hash(), whole.sim.state_hash());
  // Everything else too: colliders, footprint, budget, loads.
  EXPECT_TRUE(resumed.save() == whole.save()) << "the saved states differ";
}

TEST(Checkpoint, ALoadedTireOnAConveyorResumesBitForBit) {
  const SceneSpec s = scene("tire_on_snow.toml", {"simulation.dx=0.01", "simulation.particles_per_cell=1",
                                                  "tire.axle=\"loaded\"", "tire.load=300",
                                                  "conveyor.speed=20 mph", "tire.speed=20 mph"});
  ASSERT_TRUE(s.conveyor);
  expect_resume_matches(s, 40, 40);
}

TEST(Checkpoint, AFreeRollingLoadedTireResumesBitForBit) {
  const SceneSpec s = scene("../tests/scenes/free_wheel.toml", {"tire.axle=loaded", "tire.load=300", "tire.inertia=0.05"});
  ASSERT_TRUE(s.tire->free_spin);
  expect_resume_matches(s, 40, 40);
}

TEST(Checkpoint, ALoadedPlasticBarResumesBitForBit) {
  // Saved during the load's ramp, so that the ramp factor is part of the state.
  expect_resume_matches(scene("snow_bar.toml", {"simulation.dx=4 mm", "simulation.particles_per_cell=1"}), 5, 30);
}

TEST(Checkpoint, ThrownSnowballsResumeBitForBit) {
  // Particles crossing grid blocks every step: the breaks that decide the next reorder of the
  // particle arrays (ParticleBinning::needs_reorder) are part of the state.
  // Saved at several steps of the collision, where the particles of the two balls mix, so that
  // some of the saves fall between two reorders.
  const SceneSpec s = scene("snowball_pair.toml", {"simulation.dx=4 mm", "simulation.particles_per_cell=1"});
  for (int before = 60; before < 66; ++before) expect_resume_matches(s, before, 30);
}

TEST(Checkpoint, AnotherSceneIsRefused) {
  SteppedScene bar(scene("snow_bar.toml", {"simulation.dx=4 mm", "simulation.particles_per_cell=1"}), 1);
  bar.steps(2);
  const std::string saved = bar.save();
  SteppedScene pair(scene("snowball_pair.toml", {"simulation.dx=0.02"}), 1);
  StateReader in(saved);
  EXPECT_THROW(pair.sim.load_state(in), CheckpointError);
}

TEST(Checkpoint, ATruncatedStateIsRefused) {
  const SceneSpec s = scene("snow_bar.toml", {"simulation.dx=4 mm", "simulation.particles_per_cell=1"});
  SteppedScene bar(s, 1);
  bar.steps(2);
  const std::string saved = bar.save();
  SteppedScene again(s, 1);
  StateReader in(saved.data(), saved.size() - 9);
  EXPECT_THROW(again.sim.load_state(in), CheckpointError);
}

}  // namespace
}  // namespace firn
