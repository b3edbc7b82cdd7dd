// firn render OUTDIR [--render spheres|surface] [--video] [--set render.KEY=VALUE]... [--gl egl|osmesa]
// Re-renders a finished run from OUTDIR/particles/NNNNN.vtp and OUTDIR/scene.resolved.toml, with
// the [render] settings (and materials' colours) changed by --set, into OUTDIR/frames (and
// OUTDIR/video.mp4). Surfaces anchor their noise and crystals to the first frame's positions
// (viz/vtp_frame.hpp).
#include <dirent.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "apps/frame_surface.hpp"
#include "apps/run_rendering.hpp"
#include "engine/output/atomic_file.hpp"
#include "engine/scene/scene_reader.hpp"
#include "viz/frame_pipeline.hpp"
#include "viz/scene_render_settings.hpp"
#include "viz/surface/reconstruct_surface.hpp"
#include "viz/vtp_frame.hpp"

namespace firn::app {
namespace {

// NNNNN.vtp files of the folder, in frame order.
std::vector<std::pair<int, std::string>> particle_files(const std::string& dir) {
  std::vector<std::pair<int, std::string>> files;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (const dirent* e = ::readdir(d)) {
      const std::string name = e->d_name;
      if (name.size() == 9 && name.substr(5) == ".vtp" &&
          std::all_of(name.begin(), name.begin() + 5, [](char c) { return c >= '0' && c <= '9'; }))
        files.emplace_back(std::stoi(name.substr(0, 5)), dir + "/" + name);
    }
    ::closedir(d);
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

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
    const auto files = particle_files(o->dir + "/particles");
    if (files.empty()) {
      std::fprintf(stderr, "firn render: no particle files in %s/particles\n", o->dir.c_str());
      set_exit_status(2);
      return;
    }
    try {
      make_directories(o->dir + "/frames");
      viz::FramePipeline pipeline(viz::scene_render_settings(scene.spec), viz::parse_gl_api(o->gl),
                                  {o->dir + "/frames", o->video ? o->dir + "/video.mp4" : "", scene.spec.render.fps});
      const bool draw_surface = o->render == "surface";
      const surface::SurfaceParams params = scene_surface_params(scene.spec);
      const backend::OpenMP omp;
      const viz::VtpRestPositions rest = draw_surface ? viz::read_vtp_rest_positions(files.front().second)
                                                 : viz::VtpRestPositions{};
      for (const auto& [frame, path] : files) {
        const viz::VtpFrame particles(path, frame, scene.spec, draw_surface ? &rest : nullptr);
        viz::RenderFrame r = particles.render_frame();
        surface::SurfaceMesh mesh;
        if (draw_surface) {
          mesh = surface::reconstruct_surface(particles.particle_view(), params, omp);
          r.surface = &mesh;
        }
        pipeline.add(r);
      }
      pipeline.finish();
      std::printf("rendered %zu frames into %s/frames%s (%s)\n", files.size(), o->dir.c_str(),
                  o->video ? ", video.mp4" : "", pipeline.gl_description().c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "firn render: %s\n", e.what());
      set_exit_status(1);
    }
  });
}

}  // namespace firn::app
