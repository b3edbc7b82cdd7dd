// firn sweep SCENE --vary KEY=V1,V2[,...]... [--set KEY=VALUE]... [--out DIR] [--preview] [--jobs N]
//                  [--at T1,T2,...] [--backend serial|openmp|cuda] [--plot C1,C2,...]
//                  [--scheduler local|slurm] [--sbatch OPTION]... [--checkpoint-every TIME]
//                  [--render none|spheres|surface] [--report]
// firn sweep --collect DIR [--plot C1,C2,...] [--report]
// firn sweep --resume DIR [--jobs N] [--backend B] [--report]
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
// With --render every run draws its frames, and the sweep writes contact sheets: the middle and the
// last frame of every run side by side, DIR/contact_sheets/NNNNN.png. --report writes
// DIR/report.html (firn report DIR) once the runs have ended.
// Exit status: 0 every run ok (slurm: submitted), 1 some run not ok or not finished (slurm: sbatch
// failed), 2 bad scene or options, 130 interrupted.
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/backend_option.hpp"
#include "apps/commands.hpp"
#include "engine/scene/scene_reader.hpp"
#include "studies/report/contact_sheet.hpp"
#include "studies/sweep/local_sweep.hpp"
#include "studies/sweep/slurm_sweep.hpp"
#include "studies/sweep/sweep_collect.hpp"

namespace firn::app {
namespace {

void report(const std::string& line) { std::fprintf(stderr, "firn sweep: %s\n", line.c_str()); }

// What a sweep that ran or was collected here writes after its runs: the contact sheets when the
// runs were rendered, and with --report the page; returns the exit status, `status` unless one fails.
int finish_sweep(const sweep::SweepPlan& plan, const std::string& render, bool write_report, int status) {
  if (render != "none") {
    try {
      const std::vector<std::string> sheets = firn::report::write_contact_sheets(plan);
      if (!sheets.empty()) std::fprintf(stderr, "firn sweep: contact sheets in %s/contact_sheets\n", plan.out.c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "firn sweep: contact sheets: %s\n", e.what());
      status = status ? status : 1;
    }
  }
  if (write_report) {
    const int written = write_report_page(plan.out, "firn sweep");
    status = status ? status : written;
  }
  return status;
}

// firn sweep --collect DIR; returns the exit status.
int collect(const std::string& dir, const std::string& plot, bool write_report) {
  const sweep::SweepPlan plan = sweep::saved_plan(dir, plot, shipped_scenes());
  const sweep::CollectedSweep c = sweep::collect_sweep(plan, report);
  std::fprintf(stderr, "firn sweep --collect: %zu of %zu runs finished%s; %s/sweep.csv\n", c.finished, c.total,
               c.missing.empty() ? "" : (" (not yet: run " + c.missing + ")").c_str(), dir.c_str());
  return finish_sweep(plan, sweep::read_sweep_args(dir).render, write_report, c.missing.empty() && c.all_ok ? 0 : 1);
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  struct Options : sweep::SweepOptions {
    std::string scheduler = "local", collect, resume_dir;
    bool report = false;
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
  sweep->add_option("--render", o->render, "each run draws its frames (none, spheres or surface); the sweep writes "
                                           "contact sheets of every run's middle and last frame")
      ->check(CLI::IsMember({"none", "spheres", "surface"}))
      ->capture_default_str();
  sweep->add_flag("--report", o->report, "write DIR/report.html (firn report DIR) when the runs have ended");
  sweep->callback([o]() {
    const bool defines_runs = !o->scene.empty() || !o->varies.empty() || !o->sets.empty() || o->preview ||
                              !o->at.empty() || !o->checkpoint_every.empty() || o->render != "none";
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
                     "--vary, --set, --at, --preview, --checkpoint-every or --render with it\n",
                     reads_args.c_str());
      set_exit_status(2);
      return;
    }
    if (!o->resume_dir.empty() && o->scheduler != "local") {
      std::fprintf(stderr, "firn sweep: --resume runs here; a Slurm sweep's runs resume with firn run --resume\n");
      set_exit_status(2);
      return;
    }
    if (o->report && o->scheduler == "slurm") {
      std::fprintf(stderr, "firn sweep: a Slurm sweep's report waits for its runs: firn sweep --collect DIR --report\n");
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
        set_exit_status(collect(o->collect, o->plot, o->report));
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
      if (o->scheduler == "slurm") {
        set_exit_status(sweep::submit_slurm_sweep(*o, plan, report));
      } else {
        const int status = sweep::run_local_sweep(*o, plan, report);
        set_exit_status(status == 130 ? status : finish_sweep(plan, o->render, o->report, status));
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "firn sweep: %s\n", e.what());
      set_exit_status(1);
    }
  });
}

}  // namespace firn::app
