// The conveyor snow bed (engine/scene/conveyor.hpp) on the tire scene at a coarse grid: a roll
// longer than the bed stays bounded in particles, every particle that enters or leaves is counted,
// and the snow the tire has not reached yet is carried rigidly by the ground (an unbroken lattice).
#include <gtest/gtest.h>

#include <cmath>

#include "engine/scene/scene_reader.hpp"
#include "engine/scene/scene_stepper.hpp"
#include "kernels/backend/openmp.hpp"

namespace firn {
namespace {

TEST(Conveyor, ALongRollStaysBoundedAndTheIncomingSnowIsUndisturbed) {
  SceneOptions o;
  o.overrides = {"simulation.dx=0.01", "simulation.particles_per_cell=1", "conveyor.speed=20 mph", "tire.speed=20 mph"};
  const SceneSpec s = load_scene(std::string(FIRN_SOURCE_DIR) + "/scenes/tire_on_snow.toml", o).spec;
  SceneStepper<float, backend::OpenMP> stepper(s, backend::OpenMP(1));
  Simulation<float, backend::OpenMP>& sim = stepper.sim();
  const Conveyor& conveyor = *stepper.conveyor();
  const long initial = long(sim.particle_count());
  const double speed = s.conveyor->speed, bed_length = s.conveyor->inflow - s.conveyor->outflow;
  const double end = 1.2 * bed_length / speed;  // the ground carries 1.2 bed lengths past the tire
  const double column = double(initial) / (bed_length / (s.config.dx / s.per_axis()));  // particles per column
  long lowest = initial, highest = initial;
  while (stepper.before(end)) {
    stepper.step_toward(end);
    const long n = long(sim.particle_count());
    lowest = std::min(lowest, n), highest = std::max(highest, n);
    ASSERT_EQ(n, initial + conveyor.injected() - conveyor.removed());
  }
  EXPECT_GT(conveyor.removed(), initial);  // more than the whole initial bed has left
  // Bounded: within a few columns (plus what the tire pushes out of the bed) of the start.
  EXPECT_GT(double(lowest), double(initial) - 0.1 * double(initial));
  EXPECT_LT(double(highest), double(initial) + 4 * column);

  // Upstream of the tire (beyond its radius plus two cells), the snow sits where the ground
  // carried it: x0 - U t, to a fraction of a cell (the bed's own elastic settling).
  const ParticleView<float> pv = sim.particles();
  const double front = sim.collider(stepper.built().tire).collider.center[0] + s.tire->radius + 2 * s.config.dx;
  int upstream = 0;
  for (std::size_t p = 0; p < pv.n; ++p) {
    if (pv.x[0][p] < front) continue;
    ++upstream;
    const double dx = pv.x[0][p] - (pv.x0[0][p] - speed * sim.time()), dy = pv.x[1][p] - pv.x0[1][p],
                 dz = pv.x[2][p] - pv.x0[2][p];
    ASSERT_LT(std::sqrt(dx * dx + dy * dy + dz * dz), 0.1 * s.config.dx) << "particle " << pv.id[p];
  }
  EXPECT_GT(upstream, 100);
}

}  // namespace
}  // namespace firn
