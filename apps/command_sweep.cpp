// firn sweep SCENE --vary KEY=V1,V2[,...]... [--set KEY=VALUE]... [--out DIR] [--preview] [--jobs N]
//                  [--at T1,T2,...] [--backend serial|openmp|cuda] [--plot C1,C2,...]
//                  [--scheduler local|slurm] [--sbatch OPTION]... [--checkpoint-every TIME]
// firn sweep --collect DIR [--plot C1,C2,...]
// firn sweep --resume DIR [--jobs N] [--backend B]
// Runs every combination of the --vary values (their Cartesian product) as a child `firn run`, N at
// a time, and writes DIR/sweep.csv (one row per finished run, rewritten after each) and gnuplot
// PNG plots of scene metrics against time under DIR/plots/ (--plot, or displaced, accumulated and
// traction). Every combination is validated first:
// any scene fault is one line on standard error, exit status 2, and nothing is run or written.
// With --scheduler slurm the runs are not started here: DIR/slurm/sweep.sbatch, a Slurm job array
// of one task per combination, is submitted with sbatch, and `firn sweep --collect DIR` later reads
// the finished runs (the sweep's options are kept in DIR/sweep.args) into sweep.csv and the plots.
// --resume DIR continues an interrupted local sweep from DIR/sweep.args: finished runs are kept,
// interrupted ones resume from their checkpoints (firn run --resume), the rest run.
// Exit status: 0 every run ok (slurm: submitted), 1 some run not ok or not finished (slurm: sbatch
// failed), 2 bad scene or options, 130 interrupted.
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "apps/backend_option.hpp"
#include "apps/commands.hpp"
#include "engine/scene/scene_reader.hpp"
#include "studies/sweep/local_sweep.hpp"
#include "studies/sweep/slurm_sweep.hpp"
#include "studies/sweep/sweep_collect.hpp"

namespace firn::app {
namespace {

void report(const std::string& line) { std::fprintf(stderr, "firn sweep: %s\n", line.c_str()); }

// firn sweep --collect DIR; returns the exit status.
int collect(const std::string& dir, const std::string& plot) {
  const sweep::CollectedSweep c = sweep::collect_sweep(dir, plot, shipped_scenes(), report);
  std::fprintf(stderr, "firn sweep --collect: %zu of %zu runs finished%s; %s/sweep.csv\n", c.finished, c.total,
               c.missing.empty() ? "" : (" (not yet: run " + c.missing + ")").c_str(), dir.c_str());
  return c.missing.empty() && c.all_ok ? 0 : 1;
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  struct Options : sweep::SweepOptions {
    std::string scheduler = "local", collect, resume_dir;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sweep = app.add_subcommand("sweep", "run every combination of scene values; one row per run in sweep.csv");
  sweep->add_option("scene", o->scene, "scene file (TOML) or the name of a shipped scene");
  sweep->add_option("--vary", o->varies, "a key and its values, e.g. --vary \"tire.speed=5 mph,10 mph\" (repeatable)")
      ->allow_extra_args(false);
  sweep->add_option("--set", o->sets, "override a scene key in every run (repeatable)")->allow_extra_args(false);
  sweep->add_option("--out", o->out, "output folder (default: out/<scene name>_sweep)");
  sweep->add_flag("--preview", o->preview, "run every combination at preview resolution");
  sweep->add_option("--jobs", o->jobs, "runs at a time, each on cores/jobs threads")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  add_backend_option(sweep, o->backend);
  sweep->add_option("--at", o->at,
                    "times for the C@T columns of sweep.csv, e.g. --at 0.1,0.2 or --at \"50 ms,100 ms\"");
  sweep->add_option("--plot", o->plot,
                    "metrics.csv columns to plot against time, e.g. --plot road_fx,road_fy "
                    "(default: displaced,accumulated,traction; with --collect: those of the sweep)");
  sweep->add_option("--scheduler", o->scheduler, "local: run here, --jobs at a time; slurm: submit a job array")
      ->check(CLI::IsMember({"local", "slurm"}))
      ->capture_default_str();
  sweep->add_option("--sbatch", o->sbatch, "an sbatch option for the job array, e.g. --sbatch=--partition=debug (repeatable)")
      ->allow_extra_args(false);
  sweep->add_option("--collect", o->collect, "gather the finished runs of the sweep in DIR into sweep.csv and plots");
  sweep->add_option("--resume", o->resume_dir,
                    "continue the sweep in DIR: keep its finished runs, resume the interrupted ones, run the rest");
  sweep->add_option("--checkpoint-every", o->checkpoint_every,
                    "each run's firn run --checkpoint-every (e.g. 50ms), so that a killed sweep resumes its runs");
  sweep->callback([o]() {
    const bool defines_runs = !o->scene.empty() || !o->varies.empty() || !o->sets.empty() || o->preview ||
                              !o->at.empty() || !o->checkpoint_every.empty();
    const std::string reads_args = !o->collect.empty() ? "--collect" : !o->resume_dir.empty() ? "--resume" : "";
    if (!o->collect.empty() && !o->resume_dir.empty()) {
      std::fprintf(stderr, "firn sweep: give --collect DIR or --resume DIR, not both\n");
      set_exit_status(2);
      return;
    }
    if (reads_args.empty() ? (o->scene.empty() || o->varies.empty()) : defines_runs) {
      if (reads_args.empty())
        std::fprintf(stderr, "firn sweep: give a scene and at least one --vary, or --collect DIR, or --resume DIR\n");
      else
        std::fprintf(stderr,
                     "firn sweep: %s DIR reads the sweep's scene and values from DIR/sweep.args; give no scene, "
                     "--vary, --set, --at, --preview or --checkpoint-every with it\n",
                     reads_args.c_str());
      set_exit_status(2);
      return;
    }
    if (!o->resume_dir.empty() && o->scheduler != "local") {
      std::fprintf(stderr, "firn sweep: --resume runs here; a Slurm sweep's runs resume with firn run --resume\n");
      set_exit_status(2);
      return;
    }
    if (!o->sbatch.empty() && o->scheduler != "slurm") {
      std::fprintf(stderr, "firn sweep: --sbatch needs --scheduler slurm\n");
      set_exit_status(2);
      return;
    }
    if (!o->collect.empty()) {
      try {
        set_exit_status(collect(o->collect, o->plot));
      } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "firn sweep: %s\n", e.what());
        set_exit_status(2);
      } catch (const SceneError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        set_exit_status(2);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "firn sweep: %s\n", e.what());
        set_exit_status(1);
      }
      return;
    }
    if (!usable_backend(o->backend)) return;
    sweep::SweepPlan plan;
    try {
      if (!o->resume_dir.empty()) {  // the sweep's own options, with this call's --jobs and --backend
        const sweep::SweepOptions saved = sweep::read_sweep_args(o->resume_dir);
        const int jobs = o->jobs;
        const std::string backend = o->backend;
        static_cast<sweep::SweepOptions&>(*o) = saved;
        o->jobs = jobs;
        o->backend = backend;
        o->resume = true;
      }
      o->shipped_scenes = shipped_scenes();
      plan = sweep::make_plan(*o);
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "firn sweep: %s\n", e.what());
      set_exit_status(2);
      return;
    } catch (const SceneError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      set_exit_status(2);
      return;
    }
    try {
      sweep::save_sweep_args(*o, plan);
      set_exit_status(o->scheduler == "slurm" ? sweep::submit_slurm_sweep(*o, plan, report)
                                              : sweep::run_local_sweep(*o, plan, report));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "firn sweep: %s\n", e.what());
      set_exit_status(1);
    }
  });
}

}  // namespace firn::app
