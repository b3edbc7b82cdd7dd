// firn check SCENE [--set KEY=VALUE]... [--preview]
// Validates a scene and prints what a run would cost: particles per material, grid blocks,
// the first time step, the number of steps and memory, without stepping.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "engine/grid_preview.hpp"
#include "engine/scene/scene_lookup.hpp"
#include "engine/scene/scene_schema.hpp"
#include "engine/scene/scene_stepper.hpp"
#include "kernels/backend/serial.hpp"
#include "studies/sweep/child_process.hpp"

namespace firn::app {
namespace {

template <class T>
void check(const SceneSpec& s) {
  SceneStepper<T, backend::Serial> stepper(s, backend::Serial{});
  Simulation<T, backend::Serial>& sim = stepper.sim();
  std::printf("scene %s\nparticles %zu\n", s.name.c_str(), sim.particle_count());
  for (int m = 0; m < int(sim.material_count()); ++m) {
    const ParticleRange r = sim.material_range(m);
    std::printf("  material %s (%s): %zu particles\n", sim.material(m).name.c_str(), sim.material(m).model.c_str(),
                r.end - r.begin);
  }
  const GridPreview grid = preview_grid(sim);
  std::printf("grid_cells %d x %d x %d (dx %g m), blocks_touched %zu\n", grid.cells[0], grid.cells[1], grid.cells[2],
              s.config.dx, grid.active_blocks);
  std::printf("colliders %zu\n", sim.collider_count());
  if (s.tire)
    std::printf("tire %s, radius %g m, width %g m, tread depth %g m, %d pitches, %s axle, %s spin, tread speed %g m/s%s\n",
                s.tire->tread.c_str(), s.tire->radius, s.tire->width, s.tire->tread_depth, s.tire->pitches,
                s.tire->loaded ? "loaded" : "fixed", s.tire->free_spin ? "free" : "driven", s.tire->speed,
                s.tire->free_spin ? " at t = 0" : "");
  if (s.conveyor) {
    const ConveyorSpec& c = *s.conveyor;
    std::printf("conveyor ground speed %g m/s, snow %g m deep from x = %g to %g m", c.speed, c.depth, c.outflow, c.inflow);
    if (s.tire && c.speed > 0) std::printf(", slip ratio %g", (s.tire->speed - c.speed) / c.speed);
    std::printf("\n");
  }
  const double dt = sim.next_dt();
  std::printf("dt_first %.4g s\nsteps_estimate %.0f (at the first step's dt)\nframes %d\n", dt, std::ceil(s.end_time / dt),
              int(std::ceil(s.end_time / s.frame_interval - 1e-9)));
  const double bytes = double(grid.particle_bytes + grid.grid_bytes);
  std::printf("memory_estimate_mb %.1f (%s precision)\n", bytes / 1048576.0, s.precision.c_str());
}

}  // namespace

void add_check_command(CLI::App& app) {
  struct Options {
    std::string scene;
    std::vector<std::string> sets;
    bool preview = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("check", "validate a scene and estimate particles, grid, time step and memory");
  cmd->add_option("scene", o->scene, "scene file (TOML) or the name of a shipped scene")->required();
  cmd->add_option("--set", o->sets, "override a scene key (repeatable)");
  cmd->add_flag("--preview", o->preview, "as firn run --preview");
  cmd->callback([o]() {
    try {
      const LoadedScene scene = load_scene(scene_path(o->scene), SceneOptions{o->sets, o->preview});
      if (scene.spec.precision == "double") check<double>(scene.spec);
      else check<float>(scene.spec);
    } catch (const SceneError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      set_exit_status(2);
    }
  });
}

std::string shipped_scenes() { return shipped_scene_folder(sweep::self_executable(), FIRN_SOURCE_DIR "/scenes"); }

std::string scene_path(const std::string& scene) { return find_scene(scene, shipped_scenes()); }

void add_help_command(CLI::App& app) {
  CLI::App* help = app.add_subcommand("help", "reference documentation");
  help->require_subcommand(1);
  help->add_subcommand("scene-keys", "print docs/scenes.md: every scene key with unit, default and meaning")
      ->callback([]() { std::fputs(scene_reference_markdown().c_str(), stdout); });
  help->add_subcommand("scenes", "list the scenes shipped with firn (firn run NAME runs one)")->callback([]() {
    const std::string folder = shipped_scenes();
    const std::vector<ShippedScene> scenes = list_scenes(folder);
    if (scenes.empty()) {
      std::fprintf(stderr, "firn help scenes: no scenes in %s\n", folder.c_str());
      set_exit_status(1);
      return;
    }
    std::printf("Scenes shipped with firn, in %s (firn run NAME; a file of that name in the current folder "
                "comes first):\n", folder.c_str());
    for (const ShippedScene& s : scenes) std::printf("  %-16s %s\n", s.name.c_str(), s.summary.c_str());
  });
}

}  // namespace firn::app
