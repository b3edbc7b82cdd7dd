// firn run SCENE [--out DIR] [--set KEY=VALUE]... [--threads N] [--backend serial|openmp|cuda] [--preview] [--profile]
//                [--render none|spheres|surface] [--video] [--mesh] [--gl egl|osmesa] [--checkpoint-every TIME]
//                [--report]
// firn run --resume DIR [--threads N] [--backend ...] [--render ...] [--video] [--mesh] [--gl ...]
//                [--checkpoint-every TIME] [--report]
// With --render spheres or surface, every output frame is also drawn to frames/NNNNN.png (and
// video.mp4); surface draws the reconstructed snow surface (viz/surface/frame_surface.hpp).
// Validates the scene (any fault: one line on standard error, exit status 2, nothing written),
// runs it with progress (a redrawn line on a terminal, else a line a minute), and writes the outputs
// of DESIGN.md section 5.
// An interrupt writes DIR/checkpoint.firn, and so does --checkpoint-every at the frames it names;
// --resume continues such a run (engine/scene/checkpoint.hpp) to the end it would have reached.
// --report writes DIR/report.html (firn report DIR) when the run ends, unless it was interrupted.
// Exit status: 0 completed, 1 unstable or failed, 2 bad scene, options or checkpoint, 130 interrupted.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "apps/backend_option.hpp"
#include "apps/commands.hpp"
#include "apps/launch_table.hpp"
#include "engine/scene/checkpoint.hpp"
#include "engine/scene/scene_run.hpp"
#include "studies/sweep/run_record.hpp"
#include "viz/run_rendering.hpp"
#include "viz/surface/run_meshes.hpp"

namespace firn::app {
namespace {

std::atomic<bool> g_interrupted{false};
extern "C" void on_interrupt(int) { g_interrupted = true; }

std::string clock_text(double seconds) {
  const long s = long(seconds + 0.5);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return buf;
}

// Progress on standard error. On a terminal: one line, redrawn at most four times a second.
// Elsewhere (a log file, a batch job): a line of its own once a minute, so that a short run's log
// stays as it was and a long one's shows where it is.
class ProgressLine {
 public:
  explicit ProgressLine(bool terminal) : terminal_(terminal), last_(terminal ? Clock::time_point{} : start_) {}

  void operator()(const RunProgress& p) {
    const auto now = Clock::now();
    const double since = std::chrono::duration<double>(now - last_).count();
    if (terminal_ ? since < 0.25 && p.time < p.end_time : since < 60) return;
    last_ = now;
    const double wall = std::chrono::duration<double>(now - start_).count();
    const double eta = p.time > 0 ? wall * (p.end_time - p.time) / p.time : 0;
    std::fprintf(stderr, "%s  t = %.4g / %.4g s   frame %d/%d   step %ld   %.0f steps/s   ETA %s%s",
                 terminal_ ? "\r" : "", p.time, p.end_time, p.frame, p.frames, p.steps,
                 p.step_seconds > 0 ? double(p.steps) / p.step_seconds : 0.0, clock_text(eta).c_str(),
                 terminal_ ? "   " : "\n");
    drawn_ = terminal_;
  }
  // Ends the terminal's line so that later messages start on their own.
  void finish() {
    if (drawn_) std::fprintf(stderr, "\n");
    drawn_ = false;
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool terminal_;
  Clock::time_point start_ = Clock::now(), last_;
  bool drawn_ = false;
};

// A run whose summary.json says it finished.
bool finished_run(const std::string& out_dir) {
  const std::optional<std::string> summary = sweep::file_text(out_dir + "/summary.json");
  return summary && sweep::json_value(*summary, "status") == "ok";
}

}  // namespace

void add_run_command(CLI::App& app) {
  struct Options {
    std::string scene, out, render = "none", gl, backend = "openmp", resume, checkpoint_every;
    std::vector<std::string> sets;
    int threads = 0;
    bool preview = false, video = false, mesh = false, report = false, profile = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* run = app.add_subcommand("run", "run a scene and write its outputs");
  run->add_option("scene", o->scene, "scene file (TOML) or the name of a shipped scene (firn help scenes)");
  run->add_option("--out", o->out, "output folder (default: out/<scene name>)");
  run->add_option("--resume", o->resume, "continue the run in this output folder from its checkpoint");
  run->add_option("--checkpoint-every", o->checkpoint_every,
                  "write DIR/checkpoint.firn at the first frame after every multiple of this simulated time, "
                  "e.g. 50ms (an interrupt always writes one)");
  run->add_option("--set", o->sets, "override a scene key, e.g. --set simulation.dx=0.002 (repeatable)");
  run->add_option("--threads", o->threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  add_backend_option(run, o->backend);
  run->add_flag("--preview", o->preview, "coarser and faster: dx doubled, fewer particles per cell and frames");
  run->add_option("--render", o->render, "draw frames: none, spheres or surface")
      ->check(CLI::IsMember({"none", "spheres", "surface"}))->capture_default_str();
  run->add_flag("--video", o->video, "encode the frames to video.mp4");
  run->add_flag("--mesh", o->mesh, "write reconstructed surfaces to meshes/NNNNN.ply");
  run->add_option("--gl", o->gl, "OpenGL context: egl or osmesa")->check(CLI::IsMember({"egl", "osmesa"}));
  run->add_flag("--report", o->report, "write DIR/report.html (firn report DIR) when the run ends");
  run->add_flag("--profile", o->profile,
                "time every launch of the step loop; print the table and write it to summary.json (launch_seconds)");
  run->callback([o]() {
    auto refuse = [](const std::string& why) {
      std::fprintf(stderr, "firn run: %s\n", why.c_str());
      set_exit_status(2);
    };
    if (o->video && o->render == "none") return refuse("--video needs --render spheres or surface");
    const bool resume = !o->resume.empty();
    if (resume == !o->scene.empty()) return refuse("give a scene, or --resume DIR");
    if (resume && (!o->out.empty() || !o->sets.empty() || o->preview))
      return refuse("--resume continues the run as it was set up: no --out, --set or --preview");
    if (resume && o->video)
      return refuse("a resumed run draws only its remaining frames; make the whole video afterwards with "
                    "firn render " + o->resume + " --video");
    RunOptions options;
    if (!o->checkpoint_every.empty()) {
      try {
        options.checkpoint_every = checkpoint_interval(o->checkpoint_every);
      } catch (const std::invalid_argument& e) {
        return refuse(e.what());
      }
    }
    const std::optional<BackendKind> backend = usable_backend(o->backend);
    if (!backend) return;
    if (resume && finished_run(o->resume)) {
      std::printf("%s: the run already finished (summary.json), nothing to resume\n", o->resume.c_str());
      return;
    }
    LoadedScene scene;
    try {
      scene = resume ? load_scene(o->resume + "/scene.resolved.toml", SceneOptions{})
                     : load_scene(scene_path(o->scene), SceneOptions{o->sets, o->preview});
    } catch (const SceneError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      set_exit_status(2);
      return;
    }
    options.out_dir = resume ? o->resume : o->out.empty() ? "out/" + scene.spec.name : o->out;
    options.resume = resume;
    options.backend = *backend;
    options.threads = o->threads;
    options.profile = o->profile;
    options.interrupt = &g_interrupted;
    viz::RunRendering rendering;
    if (o->render != "none") {
      try {
        rendering = viz::start_run_rendering(scene.spec, options.out_dir, o->video, o->gl, o->render == "surface", o->threads);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "firn run: cannot render: %s\n", e.what());
        set_exit_status(2);
        return;
      }
      options.on_frame = rendering.on_frame;
    }
    // The surface's noise and crystals are anchored to the rest positions.
    if (o->mesh || o->render == "surface") options.rest_positions = true;
    if (o->mesh) {
      const auto draw = options.on_frame;
      const auto meshes = surface::start_run_meshes(scene.spec, options.out_dir, o->threads);
      options.on_frame = [draw, meshes](const FrameDescription& f) {
        if (draw) draw(f);
        meshes(f);
      };
    }
    ProgressLine progress(isatty(STDERR_FILENO));
    options.progress = std::ref(progress);
    std::signal(SIGINT, on_interrupt);
    std::signal(SIGTERM, on_interrupt);
    RunSummary s;
    try {
      s = run_scene(scene, options);
    } catch (const SceneError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      set_exit_status(2);
      return;
    } catch (const CheckpointError& e) {
      return refuse(std::string("cannot resume: ") + e.what());
    } catch (const std::exception& e) {
      progress.finish();
      std::fprintf(stderr, "firn run: %s\n", e.what());
      set_exit_status(1);
      return;
    }
    progress.finish();
    if (rendering.finish) {
      try {
        rendering.finish();
      } catch (const std::exception& e) {
        std::fprintf(stderr, "firn run: writing frames: %s\n", e.what());
        set_exit_status(1);
        return;
      }
    }
    if (s.status != "ok") {
      std::fprintf(stderr, "firn run: %s: %s (outputs so far in %s)\n", s.status.c_str(), s.error.c_str(),
                   options.out_dir.c_str());
      if (std::filesystem::exists(checkpoint_path(options.out_dir))) {
        if (s.status == "interrupted")
          std::fprintf(stderr, "firn run: continue with: firn run --resume %s\n", options.out_dir.c_str());
        else
          std::fprintf(stderr, "firn run: the last output frame's state is in %s (firn run --resume repeats the run from it)\n",
                       checkpoint_path(options.out_dir).c_str());
      }
      if (o->report && s.status != "interrupted") write_report_page(options.out_dir, "firn run");
      set_exit_status(s.status == "interrupted" ? 130 : 1);
      return;
    }
    // A GPU run has no thread count to speak of.
    const std::string where = s.backend == "cuda" ? s.backend : s.backend + ", " + std::to_string(s.threads) + " threads";
    std::printf("%s: ok, %zu particles, %ld steps, %.1f s (%.3g particle-steps/s on %s), outputs in %s\n",
                scene.spec.name.c_str(), s.particles, s.steps, s.wall_seconds, s.particle_steps_per_second(),
                where.c_str(), options.out_dir.c_str());
    if (o->profile && !resume) print_launch_table(s.launches, s.step_seconds, s.steps);
    if (rendering.finish)
      std::printf("frames in %s/frames%s (%s)\n", options.out_dir.c_str(), o->video ? ", video.mp4" : "",
                  rendering.description.c_str());
    if (o->mesh) std::printf("surfaces in %s/meshes\n", options.out_dir.c_str());
    if (o->report) set_exit_status(write_report_page(options.out_dir, "firn run"));
  });
}

}  // namespace firn::app
