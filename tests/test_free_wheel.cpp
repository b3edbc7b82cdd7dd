// A free-rolling wheel (issue 16; [tire] spin = "free", engine/collider_body.hpp): its spin about
// the axle turns under the snow's torque alone. On a coarse conveyor bed: a wheel set down
// without spin and one set down rolling with the ground settle at the same slip, a loaded wheel
// that the snow cannot carry stops the run at the ground instead of falling through it, and a
// frictionless wheel towed over an elastic bed meets only the discretisation's small resistance.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "engine/scene/scene_reader.hpp"
#include "engine/scene/scene_stepper.hpp"
#include "kernels/backend/openmp.hpp"

namespace firn {
namespace {

// A free-rolling slick tire on a fixed axle, 25 mm into a coarse conveyor bed at 10 mph.
SceneSpec tire_scene(std::vector<std::string> overrides) {
  SceneOptions o;
  o.overrides = std::move(overrides);
  return load_scene(std::string(FIRN_SOURCE_DIR) + "/tests/scenes/free_wheel.toml", o).spec;
}

TEST(FreeWheel, StartsRollingWithTheGroundAndDefaultsToADisksInertia) {
  const SceneSpec s = tire_scene({"tire.mass=8"});
  EXPECT_TRUE(s.tire->free_spin);
  EXPECT_EQ(s.tire->speed, s.conveyor->speed);
  EXPECT_DOUBLE_EQ(s.tire->inertia, 0.5 * 8 * s.tire->radius * s.tire->radius);
  SceneStepper<float, backend::OpenMP> stepper(s, backend::OpenMP(1));
  EXPECT_DOUBLE_EQ(stepper.sim().collider(stepper.built().tire).collider.angular_velocity[2],
                   -s.conveyor->speed / s.tire->radius);
}

// The slip ratio (tread speed - ground speed) / ground speed after running the scene to `end`
// from the spin w0 about z (the tread at the ground moves toward -x for w0 < 0).
double slip_after(const SceneSpec& s, double w0, double end) {
  SceneStepper<float, backend::OpenMP> stepper(s, backend::OpenMP(1));
  ColliderBody& tire = stepper.sim().collider(stepper.built().tire);
  tire.collider.angular_velocity[2] = w0;
  while (stepper.before(end)) stepper.step_toward(end);
  return (-tire.collider.angular_velocity[2] * s.tire->radius - s.conveyor->speed) / s.conveyor->speed;
}

// The snow decides a free wheel's spin: set down without spin, the wheel is spun up by the snow
// the ground drags under it, and started at the ground's speed it slows (the snow ahead of the
// rigid tread brakes it: a towed wheel skids); both settle at the same slip. A driven wheel keeps
// the spin it is given.
TEST(FreeWheel, SettlesAtTheSameSlipFromRestAndFromTheGroundSpeed) {
  const SceneSpec s = tire_scene({"tire.inertia=0.002"});  // a light wheel settles in a few tens of ms
  const double rolling = -s.conveyor->speed / s.tire->radius;
  const double from_rest = slip_after(s, 0, 0.1), from_rolling = slip_after(s, rolling, 0.1);
  EXPECT_GT(from_rest, -0.8);       // spun up from -1
  EXPECT_LT(from_rolling, -0.05);   // slowed from 0
  EXPECT_NEAR(from_rest, from_rolling, 0.1);
  const SceneSpec driven = tire_scene({"tire.spin=driven", "tire.speed=10 mph"});
  EXPECT_EQ(slip_after(driven, 0, 0.01), -1);
}

// A towed wheel without friction on a bed that stores all its energy (the hard snow made elastic:
// sigma_y0 far above any stress it meets) meets no resistance in the continuum: the rolling is
// steady and slower than the bed's waves (10 mph against a shear wave speed of 12 m/s), so nothing
// is dissipated or radiated. The horizontal force it meets here is the discretisation's loss
// (docs/contact.md, "The towed tire's rolling resistance: what is numerical"): 1.54% of the load at
// this grid (dx 10 mm, one particle per cell), 1.00% at the thesis scene's. A bilateral contact,
// which holds the bed where it leaves the tread (boundary "slip"), nearly doubles it: 2.73%.
// The wheel's resistance coefficient -F_x / F_y over 0.15-0.25 s, towed without friction over the
// elastic bed, with the overrides given.
double elastic_bed_resistance(std::vector<std::string> overrides) {
  for (const char* o : {"materials.snow.sigma_y0=1e9", "tire.friction_law=coulomb", "tire.friction=0",
                        "simulation.end_time=0.25 s"})
    overrides.push_back(o);
  const SceneSpec s = tire_scene(overrides);
  SceneStepper<float, backend::OpenMP> stepper(s, backend::OpenMP(1));
  ColliderBody& tire = stepper.sim().collider(stepper.built().tire);
  while (stepper.before(0.15)) stepper.step_toward(0.15);  // past the start: the bed has passed under the tire
  tire.reset_impulse();
  while (stepper.before(0.25)) stepper.step_toward(0.25);
  const double traction = tire.impulse[0] / tire.impulse_time, load = tire.impulse[1] / tire.impulse_time;
  EXPECT_GT(load, 1000);  // 25 mm into the elastic bed
  EXPECT_LT(traction, 0);
  return -traction / load;
}

TEST(FreeWheel, AFrictionlessWheelOnAnElasticBedMeetsOnlyTheDiscretisationsSmallResistance) {
  EXPECT_LT(elastic_bed_resistance({}), 0.018);
}

// The penalty contact at the particles (`contact = "penalty"`, kernels/step/penalty_contact.hpp)
// stores the energy it takes where the node contact's projection dissipates some at every step:
// on the same bed the wheel meets 0.76% of the load against the node contact's 1.54% (and 0.52% against
// 1.65% at the preview of scenes/tire_towed_on_snow.toml, 0.12% against 1.44% at its dx 8 mm).
TEST(FreeWheel, APenaltyContactMeetsLessOfTheNumericalResistance) {
  EXPECT_LT(elastic_bed_resistance({"tire.contact=penalty"}), 0.009);
}

// The footprint map is summed at the nodes the tire holds, and a penalty tire holds none: its
// footprint defaults to off (an explicit `footprint = true` is refused: tests/scenes/malformed).
TEST(FreeWheel, APenaltyTiresFootprintMapDefaultsToOff) {
  EXPECT_TRUE(tire_scene({}).metrics.footprint);
  EXPECT_FALSE(tire_scene({"tire.contact=penalty"}).metrics.footprint);
}

// 4 kN on a 10 kg wheel, far more than 50 mm of the thesis' soft snow holds.
TEST(FreeWheel, ALoadedWheelTheSnowCannotCarryStopsAtTheGround) {
  const SceneSpec s =
      tire_scene({"tire.axle=loaded", "tire.load=4000", "materials.snow.preset=thesis_soft_snow"});
  SceneStepper<float, backend::OpenMP> stepper(s, backend::OpenMP(1));
  try {
    while (stepper.before(0.5)) stepper.step_toward(0.5);
    FAIL() << "the tire fell through the ground";
  } catch (const StabilityError& e) {
    EXPECT_NE(std::string(e.what()).find("went through the ground"), std::string::npos) << e.what();
  }
  const ColliderBody& tire = stepper.sim().collider(stepper.built().tire);
  const double below = s.conveyor->ground - (tire.collider.center[1] - s.tire->radius);
  EXPECT_GT(below, s.config.dx);
  EXPECT_LT(below, 1.5 * s.config.dx);  // stopped there, not after falling on
}

}  // namespace
}  // namespace firn
