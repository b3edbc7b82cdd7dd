// firn render OUTDIR [--render spheres|surface] [--video] [--set render.KEY=VALUE]... [--gl egl|osmesa]
// Re-renders a finished run from OUTDIR/particles/NNNNN.vtp and OUTDIR/scene.resolved.toml, with
// the [render] settings (and materials' colours) changed by --set, into OUTDIR/frames (and
// OUTDIR/video.mp4), by viz/rerender_run.hpp.
#include <cstdio>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "engine/scene/scene_reader.hpp"
#include "viz/rerender_run.hpp"

namespace firn::app {

void add_render_command(CLI::App& app) {
  struct Options {
    std::string dir, render = "spheres", gl;
    std::vector<std::string> sets;
    bool video = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* c = app.add_subcommand("render", "re-render a finished run from its particle files");
  c->add_option("outdir", o->dir, "the run's output folder (with scene.resolved.toml and particles/)")->required();
  c->add_option("--render", o->render, "style: spheres or surface")->check(CLI::IsMember({"spheres", "surface"}))
      ->capture_default_str();
  c->add_flag("--video", o->video, "encode the frames to video.mp4");
  c->add_option("--set", o->sets,
                "override a render key or a material's colour, e.g. --set render.color_by=speed (repeatable)");
  c->add_option("--gl", o->gl, "OpenGL context: egl or osmesa")->check(CLI::IsMember({"egl", "osmesa"}));
  c->callback([o]() {
    // Only what changes the picture, not the run: [render] keys and the materials' colours.
    auto drawing_only = [](const std::string& set) {
      const std::string key = set.substr(0, set.find('='));
      return key.rfind("render.", 0) == 0 ||
             (key.rfind("materials.", 0) == 0 && key.size() > 16 && key.compare(key.size() - 6, 6, ".color") == 0);
    };
    for (const std::string& s : o->sets)
      if (!drawing_only(s)) {
        std::fprintf(stderr, "firn render: --set %s: only render.KEY and materials.NAME.color can change after a run\n",
                     s.c_str());
        set_exit_status(2);
        return;
      }
    LoadedScene scene;
    try {
      scene = load_scene(o->dir + "/scene.resolved.toml", SceneOptions{o->sets, false});
    } catch (const SceneError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      set_exit_status(2);
      return;
    }
    const auto files = viz::particle_files(o->dir + "/particles");
    if (files.empty()) {
      std::fprintf(stderr, "firn render: no particle files in %s/particles%s\n", o->dir.c_str(),
                   scene.spec.output.particles ? "" : " (the run had output.particles = false)");
      set_exit_status(2);
      return;
    }
    try {
      const viz::RerenderResult r =
          viz::rerender_run(scene.spec, files, {o->dir, o->render == "surface", o->video, o->gl});
      std::printf("rendered %zu frames into %s/frames%s (%s)\n", r.frames, o->dir.c_str(), o->video ? ", video.mp4" : "",
                  r.description.c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "firn render: %s\n", e.what());
      set_exit_status(1);
    }
  });
}

}  // namespace firn::app
