// firn sweep SCENE --vary KEY=V1,V2[,...]... [--set KEY=VALUE]... [--out DIR] [--preview] [--jobs N]
//                  [--at T1,T2,...] [--backend serial|openmp|cuda]
// Runs every combination of the --vary values (their Cartesian product) as a child `firn run`, N at
// a time, and writes DIR/sweep.csv (one row per finished run, rewritten after each) and gnuplot
// PNG plots of the plotted scene metrics under DIR/plots/. Every combination is validated first:
// any scene fault is one line on standard error, exit status 2, and nothing is run or written.
// Exit status: 0 every run ok, 1 some run not ok, 2 bad scene or options, 130 interrupted.
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/backend_option.hpp"
#include "apps/commands.hpp"
#include "apps/sweep/child_process.hpp"
#include "apps/sweep/combinations.hpp"
#include "apps/sweep/gnuplot.hpp"
#include "apps/sweep/metric_plot.hpp"
#include "apps/sweep/sweep_table.hpp"
#include "engine/output/atomic_file.hpp"
#include "engine/scene/scene_reader.hpp"
#include "engine/units.hpp"

namespace firn::app {
namespace {

using namespace firn::sweep;
using Clock = std::chrono::steady_clock;

struct Options {
  std::string scene, out, at, backend = "openmp";
  std::vector<std::string> varies, sets;
  int jobs = 1;
  bool preview = false;
};

struct Plan {
  std::vector<VariedKey> keys;
  std::vector<std::vector<std::string>> combinations;
  std::vector<double> at_times;
  std::string out;
};

// Reads the options and loads every combination's scene; throws std::invalid_argument (bad
// options) or SceneError (a bad scene or value) before anything is written.
Plan make_plan(const Options& o) {
  Plan plan;
  for (const std::string& v : o.varies) {
    plan.keys.push_back(parse_vary(v));
    for (std::size_t k = 0; k + 1 < plan.keys.size(); ++k)
      if (plan.keys[k].key == plan.keys.back().key)
        throw std::invalid_argument("--vary " + plan.keys.back().key + " is given twice");
  }
  if (!o.at.empty())
    for (const std::string& t : split_value_list(o.at)) {
      try {
        plan.at_times.push_back(parse_quantity(t, Quantity::time));
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("--at " + t + ": " + e.what());
      }
    }
  plan.combinations = cartesian_product(plan.keys);
  std::string name;
  for (const auto& values : plan.combinations) {
    std::vector<std::string> overrides = o.sets;
    for (const std::string& s : set_arguments(plan.keys, values)) overrides.push_back(s);
    name = load_scene(o.scene, SceneOptions{overrides, o.preview}).spec.name;
  }
  plan.out = o.out.empty() ? "out/" + name + "_sweep" : o.out;
  return plan;
}

int cores() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1L, sysconf(_SC_NPROCESSORS_ONLN));
}

// "42.0 s", "3.5 min" or "1.25 h".
std::string duration_text(double seconds) {
  char buf[32];
  if (seconds < 60)
    std::snprintf(buf, sizeof buf, "%.1f s", seconds);
  else if (seconds < 3600)
    std::snprintf(buf, sizeof buf, "%.1f min", seconds / 60);
  else
    std::snprintf(buf, sizeof buf, "%.2f h", seconds / 3600);
  return buf;
}

struct Running {
  std::size_t index;
  Clock::time_point start;
};

class Sweep {
 public:
  Sweep(const Options& o, Plan plan) : o_(o), plan_(std::move(plan)), threads_(std::max(1, cores() / o.jobs)) {}
  // Stops the runs still going if run() ends by an exception.
  ~Sweep() {
    for (const auto& [pid, r] : running_) kill(pid, SIGTERM);
    for (const auto& [pid, r] : running_) wait_child(pid);
    if (masked_) sigprocmask(SIG_SETMASK, &previous_mask_, nullptr);
  }

  // Runs the plan; returns the exit status.
  int run() {
    const std::size_t total = plan_.combinations.size();
    std::filesystem::create_directories(plan_.out + "/runs");
    std::fprintf(stderr, "firn sweep: %zu runs, %d at a time on %d thread%s each, outputs in %s\n", total, o_.jobs,
                 threads_, threads_ == 1 ? "" : "s", plan_.out.c_str());
    // SIGINT, SIGTERM and SIGCHLD are taken synchronously with sigwaitinfo, so none is missed
    // between launching and waiting; children start with them unblocked.
    sigset_t signals;
    sigemptyset(&signals);
    for (const int s : {SIGINT, SIGTERM, SIGCHLD}) sigaddset(&signals, s);
    sigprocmask(SIG_BLOCK, &signals, &previous_mask_);
    masked_ = true;
    const auto start = Clock::now();
    std::size_t next = 0, done = 0;
    bool interrupted = false;
    while (true) {
      while (!interrupted && next < total && running_.size() < std::size_t(o_.jobs)) launch(next++);
      if (running_.empty()) break;
      siginfo_t info;
      const int s = sigwaitinfo(&signals, &info);
      if (s == SIGINT || s == SIGTERM) {
        if (!interrupted) {
          std::fprintf(stderr, "firn sweep: interrupted; stopping %zu running run%s\n", running_.size(),
                       running_.size() == 1 ? "" : "s");
          for (const auto& [pid, r] : running_) kill(pid, SIGTERM);
        }
        interrupted = true;
      }
      for (int status; true;) {
        const pid_t pid = waitpid(-1, &status, WNOHANG);
        if (pid <= 0) break;
        const auto it = running_.find(pid);
        if (it == running_.end()) continue;
        const Running r = it->second;
        running_.erase(it);
        finish(r, exit_status_of(status), ++done, start, interrupted);
      }
    }
    write_table();  // also when no run finished
    int status = interrupted ? 130 : 0;
    if (!interrupted) {
      for (const auto& [index, record] : finished_)
        if (record.status != "ok") status = 1;
      plot();
      // An interrupt during plotting is still one.
      const timespec now{0, 0};
      for (int s; (s = sigtimedwait(&signals, nullptr, &now)) > 0;)
        if (s != SIGCHLD) status = 130;
    }
    sigprocmask(SIG_SETMASK, &previous_mask_, nullptr);
    masked_ = false;
    std::fprintf(stderr, "firn sweep: %zu of %zu runs finished in %s; %s/sweep.csv\n", finished_.size(), total,
                 duration_text(seconds_since(start)).c_str(), plan_.out.c_str());
    return status;
  }

 private:
  static double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

  std::string run_dir(std::size_t index) const {
    return plan_.out + "/runs/" + run_name(index + 1, plan_.combinations.size(), plan_.combinations[index]);
  }

  void launch(std::size_t index) {
    const std::string dir = run_dir(index);
    std::filesystem::create_directories(dir);
    ChildSpec child;
    child.argv = {self_, "run", o_.scene, "--out", dir};
    std::vector<std::string> overrides = o_.sets;
    for (const std::string& s : set_arguments(plan_.keys, plan_.combinations[index])) overrides.push_back(s);
    for (const std::string& s : overrides) child.argv.insert(child.argv.end(), {"--set", s});
    child.argv.insert(child.argv.end(), {"--threads", std::to_string(threads_), "--backend", o_.backend});
    if (o_.preview) child.argv.push_back("--preview");
    child.log_path = dir + "/log.txt";
    running_[start_child(child)] = {index, Clock::now()};
  }

  // Reports a run that ended and, unless the sweep stopped it, gives it its row in sweep.csv.
  void finish(const Running& r, int exit_status, std::size_t done, Clock::time_point start, bool stopping) {
    RunRecord record;
    record.values = plan_.combinations[r.index];
    read_run_outputs(run_dir(r.index), record);
    std::string what;
    for (std::size_t k = 0; k < plan_.keys.size(); ++k)
      what += (k ? " " : "") + plan_.keys[k].key + "=" + record.values[k];
    const std::size_t total = plan_.combinations.size();
    std::string line = "firn sweep: [" + std::to_string(done) + "/" + std::to_string(total) + "] run " +
                       std::to_string(r.index + 1) + ", " + what + ": " + record.status;
    if (record.status != "ok")
      line += " (exit status " + std::to_string(exit_status) + ", see " + run_dir(r.index) + "/log.txt)";
    line += ", " + duration_text(seconds_since(r.start));
    if (done < total && !stopping)
      line += "; ETA " + duration_text(seconds_since(start) / double(done) * double(total - done));
    std::fprintf(stderr, "%s\n", line.c_str());
    if (stopping && record.status == "interrupted") return;  // stopped by the sweep's interrupt: no row
    finished_[r.index] = std::move(record);
    write_table();
  }

  void write_table() const {
    std::vector<std::string> keys;
    for (const VariedKey& k : plan_.keys) keys.push_back(k.key);
    write_file_atomically(plan_.out + "/sweep.csv", sweep_csv(keys, finished(), plan_.at_times));
  }

  // The finished runs in run order, whatever order they finished in.
  std::vector<RunRecord> finished() const {
    std::vector<RunRecord> records;
    for (const auto& [index, record] : finished_) records.push_back(record);
    return records;
  }

  void plot() {
    const std::string dir = plan_.out + "/plots";
    const std::vector<RunRecord> runs = finished();
    for (const std::string& metric : plotted_metrics) {
      const auto plot = metric_plot(metric, plan_.keys, runs);
      if (!plot) continue;
      if (draw_plot_or_warn("firn sweep", dir, metric, *plot) == PlotStatus::no_gnuplot) return;
    }
  }

  const Options& o_;
  const Plan plan_;
  const int threads_;
  const std::string self_ = self_executable();
  std::map<pid_t, Running> running_;
  std::map<std::size_t, RunRecord> finished_;  // by run index
  sigset_t previous_mask_;
  bool masked_ = false;
};

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  CLI::App* sweep = app.add_subcommand("sweep", "run every combination of scene values; one row per run in sweep.csv");
  sweep->add_option("scene", o->scene, "scene file (TOML)")->required();
  sweep->add_option("--vary", o->varies, "a key and its values, e.g. --vary \"tire.speed=5 mph,10 mph\" (repeatable)")
      ->required()
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
  sweep->callback([o]() {
    if (!usable_backend(o->backend)) return;
    Plan plan;
    try {
      plan = make_plan(*o);
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
      set_exit_status(Sweep(*o, std::move(plan)).run());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "firn sweep: %s\n", e.what());
      set_exit_status(1);
    }
  });
}

}  // namespace firn::app
