// firn check SCENE [--set KEY=VALUE]... [--preview]
// Validates a scene and prints what a run would cost: particles per material, grid blocks,
// the first time step, the number of steps and memory, without stepping.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "engine/scene/scene_builder.hpp"
#include "engine/scene/scene_lookup.hpp"
#include "engine/scene/scene_schema.hpp"
#include "kernels/backend/serial.hpp"
#include "studies/sweep/child_process.hpp"

namespace firn::app {
namespace {

// Blocks of 4^3 nodes that the particles' quadratic or cubic stencils touch.
template <class T>
std::size_t touched_blocks(const SceneSpec& s, const ParticleView<T>& pv) {
  int blocks[3];
  for (int d = 0; d < 3; ++d)
    blocks[d] = int(std::lround((s.config.domain_max[d] - s.config.domain_min[d]) / s.config.dx)) / kBlockSize + 1;
  std::vector<char> used(static_cast<std::size_t>(blocks[0]) * blocks[1] * blocks[2], 0);
  const int support = s.config.shape == Shape::quadratic ? 3 : 4;
  const double offset = s.config.shape == Shape::quadratic ? 0.5 : 1.0;
  for (std::size_t p = 0; p < pv.n; ++p) {
    int lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {
      const int base = int(std::floor((pv.x[d][p] - s.config.domain_min[d]) / s.config.dx - offset));
      lo[d] = std::clamp(base / kBlockSize, 0, blocks[d] - 1);
      hi[d] = std::clamp((base + support - 1) / kBlockSize, 0, blocks[d] - 1);
    }
    for (int i = lo[0]; i <= hi[0]; ++i)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int k = lo[2]; k <= hi[2]; ++k) used[(std::size_t(i) * blocks[1] + j) * blocks[2] + k] = 1;
  }
  return std::size_t(std::count(used.begin(), used.end(), 1));
}

template <class T>
void check(const SceneSpec& s) {
  Simulation<T, backend::Serial> sim(s.config);
  build_scene(s, sim);
  sim.prepare();
  const ParticleView<T> pv = sim.particles();
  std::printf("scene %s\nparticles %zu\n", s.name.c_str(), sim.particle_count());
  std::vector<std::size_t> per_material(sim.material_count(), 0);
  for (std::size_t p = 0; p < pv.n; ++p) ++per_material[std::size_t(sim.material_of(p))];
  for (std::size_t m = 0; m < per_material.size(); ++m)
    std::printf("  material %s (%s): %zu particles\n", sim.material(int(m)).name.c_str(),
                sim.material(int(m)).model.c_str(), per_material[m]);
  const std::size_t blocks = touched_blocks(s, pv);
  std::printf("grid_cells %d x %d x %d (dx %g m), blocks_touched %zu\n",
              int(std::lround((s.config.domain_max[0] - s.config.domain_min[0]) / s.config.dx)),
              int(std::lround((s.config.domain_max[1] - s.config.domain_min[1]) / s.config.dx)),
              int(std::lround((s.config.domain_max[2] - s.config.domain_min[2]) / s.config.dx)), s.config.dx, blocks);
  std::printf("colliders %zu\n", sim.collider_count());
  if (s.tire)
    std::printf("tire %s, radius %g m, width %g m, tread depth %g m, %d pitches, %s axle, tread speed %g m/s\n",
                s.tire->tread.c_str(), s.tire->radius, s.tire->width, s.tire->tread_depth, s.tire->pitches,
                s.tire->loaded ? "loaded" : "fixed", s.tire->speed);
  if (s.conveyor) {
    const ConveyorSpec& c = *s.conveyor;
    std::printf("conveyor ground speed %g m/s, snow %g m deep from x = %g to %g m", c.speed, c.depth, c.outflow, c.inflow);
    if (s.tire && c.speed > 0) std::printf(", slip ratio %g", (s.tire->speed - c.speed) / c.speed);
    std::printf("\n");
  }
  const double dt = sim.next_dt();
  std::printf("dt_first %.4g s\nsteps_estimate %.0f (at the first step's dt)\nframes %d\n", dt, std::ceil(s.end_time / dt),
              int(std::ceil(s.end_time / s.frame_interval - 1e-9)));
  // Every allocated particle column, the binning arrays (about 3 words a particle) and the blocks.
  const double channels = s.config.transfer == Transfer::flip ? 8 : 4;
  const double bytes = double(pv.n) * (double(sim.bytes_per_particle()) + 12) + double(blocks) * kBlockNodes * channels * sizeof(T);
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
