// firn sweep SCENE --vary KEY=V1,V2[,...]... [--set KEY=VALUE]... [--out DIR] [--preview] [--jobs N]
//                  [--at T1,T2,...] [--backend serial|openmp|cuda] [--plot C1,C2,...]
//                  [--scheduler local|slurm] [--sbatch OPTION]...
// firn sweep --collect DIR [--plot C1,C2,...]
// Runs every combination of the --vary values (their Cartesian product) as a child `firn run`, N at
// a time, and writes DIR/sweep.csv (one row per finished run, rewritten after each) and gnuplot
// PNG plots of scene metrics against time under DIR/plots/ (--plot, or displaced, accumulated and
// traction). Every combination is validated first:
// any scene fault is one line on standard error, exit status 2, and nothing is run or written.
// With --scheduler slurm the runs are not started here: DIR/slurm/sweep.sbatch, a Slurm job array
// of one task per combination, is submitted with sbatch, and `firn sweep --collect DIR` later reads
// the finished runs (the sweep's options are kept in DIR/sweep.args) into sweep.csv and the plots.
// Exit status: 0 every run ok (slurm: submitted), 1 some run not ok or not finished (slurm: sbatch
// failed), 2 bad scene or options, 130 interrupted.
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/backend_option.hpp"
#include "apps/commands.hpp"
#include "engine/output/atomic_file.hpp"
#include "engine/scene/scene_reader.hpp"
#include "engine/scene/units.hpp"
#include "studies/sweep/child_process.hpp"
#include "studies/sweep/combinations.hpp"
#include "studies/sweep/gnuplot.hpp"
#include "studies/sweep/metric_plot.hpp"
#include "studies/sweep/run_record.hpp"
#include "studies/sweep/slurm_job.hpp"
#include "studies/sweep/sweep_table.hpp"

namespace firn::app {
namespace {

using namespace firn::sweep;
using Clock = std::chrono::steady_clock;

struct Options {
  std::string scene, out, at, plot, backend = "openmp", scheduler = "local", collect;
  std::vector<std::string> varies, sets, sbatch;
  int jobs = 1;
  bool preview = false;
};

// DIR/sweep.args: the options that define the sweep's runs, one "name=value" a line, so that
// --collect can rebuild the plan.
std::string sweep_args_text(const Options& o, const std::string& scene) {
  std::string text = "scene=" + scene + "\n";
  for (const std::string& v : o.varies) text += "vary=" + v + "\n";
  for (const std::string& v : o.sets) text += "set=" + v + "\n";
  if (!o.at.empty()) text += "at=" + o.at + "\n";
  if (!o.plot.empty()) text += "plot=" + o.plot + "\n";
  if (o.preview) text += "preview=true\n";
  return text;
}

Options read_sweep_args(const std::string& dir) {
  std::ifstream in(dir + "/sweep.args");
  if (!in) throw std::invalid_argument("--collect " + dir + ": no sweep.args there (not a sweep's output folder)");
  Options o;
  o.out = dir;
  for (std::string line; std::getline(in, line);) {
    const auto eq = line.find('=');
    const std::string name = line.substr(0, eq), value = eq == std::string::npos ? "" : line.substr(eq + 1);
    if (name == "scene") o.scene = value;
    else if (name == "vary") o.varies.push_back(value);
    else if (name == "set") o.sets.push_back(value);
    else if (name == "at") o.at = value;
    else if (name == "plot") o.plot = value;
    else if (name == "preview") o.preview = value == "true";
    else throw std::invalid_argument(dir + "/sweep.args: unknown line '" + line + "'");
  }
  return o;
}

struct Plan {
  std::vector<VariedKey> keys;
  std::vector<std::vector<std::string>> combinations;
  std::vector<double> at_times;
  std::vector<std::string> plots;  // metric columns; a named one that no run writes is reported
  bool plots_named = false;
  std::string scene;  // the scene file, as an absolute path: the runs may start elsewhere
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
  plan.plots_named = !o.plot.empty();
  plan.plots = plan.plots_named ? split_value_list(o.plot) : default_plotted_metrics;
  plan.combinations = cartesian_product(plan.keys);
  plan.scene = std::filesystem::absolute(scene_path(o.scene)).string();
  std::string name;
  for (const auto& values : plan.combinations) {
    std::vector<std::string> overrides = o.sets;
    for (const std::string& s : set_arguments(plan.keys, values)) overrides.push_back(s);
    name = load_scene(plan.scene, SceneOptions{overrides, o.preview}).spec.name;
  }
  plan.out = o.out.empty() ? "out/" + name + "_sweep" : o.out;
  return plan;
}

std::string run_dir(const Plan& plan, std::size_t index) {
  return plan.out + "/runs/" + run_name(index + 1, plan.combinations.size(), plan.combinations[index]);
}

// The `firn run` command line of run `index`, without --threads.
std::vector<std::string> run_command(const Options& o, const Plan& plan, std::size_t index, const std::string& self) {
  std::vector<std::string> argv = {self, "run", plan.scene, "--out", run_dir(plan, index)};
  std::vector<std::string> overrides = o.sets;
  for (const std::string& s : set_arguments(plan.keys, plan.combinations[index])) overrides.push_back(s);
  for (const std::string& s : overrides) argv.insert(argv.end(), {"--set", s});
  if (o.preview) argv.push_back("--preview");
  argv.insert(argv.end(), {"--backend", o.backend});
  return argv;
}

// sweep.csv and the plots from the runs that have finished so far.
class SweepTable {
 public:
  explicit SweepTable(const Plan& plan) : plan_(plan) {}

  void add(std::size_t index, RunRecord record) { finished_[index] = std::move(record); }
  std::size_t size() const { return finished_.size(); }
  bool all_ok() const {
    for (const auto& [index, record] : finished_)
      if (record.status != "ok") return false;
    return true;
  }

  void write() const {
    std::vector<std::string> keys;
    for (const VariedKey& k : plan_.keys) keys.push_back(k.key);
    write_file_atomically(plan_.out + "/sweep.csv", sweep_csv(keys, finished(), plan_.at_times));
  }

  void plot() const {
    const std::string dir = plan_.out + "/plots";
    const std::vector<RunRecord> runs = finished();
    for (const std::string& metric : plan_.plots) {
      const auto plot = metric_plot(metric, plan_.keys, runs);
      if (!plot) {
        if (plan_.plots_named) std::fprintf(stderr, "firn sweep: --plot %s: no finished run wrote it\n", metric.c_str());
        continue;
      }
      if (draw_plot_or_warn("firn sweep", dir, metric, *plot) == PlotStatus::no_gnuplot) return;
    }
  }

 private:
  // The finished runs in run order, whatever order they finished in.
  std::vector<RunRecord> finished() const {
    std::vector<RunRecord> records;
    for (const auto& [index, record] : finished_) records.push_back(record);
    return records;
  }

  const Plan& plan_;
  std::map<std::size_t, RunRecord> finished_;  // by run index
};

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
  Sweep(const Options& o, const Plan& plan) : o_(o), plan_(plan), threads_(std::max(1, cores() / o.jobs)), table_(plan) {}
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
    table_.write();  // also when no run finished
    int status = interrupted ? 130 : 0;
    if (!interrupted) {
      if (!table_.all_ok()) status = 1;
      table_.plot();
      // An interrupt during plotting is still one.
      const timespec now{0, 0};
      for (int s; (s = sigtimedwait(&signals, nullptr, &now)) > 0;)
        if (s != SIGCHLD) status = 130;
    }
    sigprocmask(SIG_SETMASK, &previous_mask_, nullptr);
    masked_ = false;
    std::fprintf(stderr, "firn sweep: %zu of %zu runs finished in %s; %s/sweep.csv\n", table_.size(), total,
                 duration_text(seconds_since(start)).c_str(), plan_.out.c_str());
    return status;
  }

 private:
  static double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

  void launch(std::size_t index) {
    const std::string dir = run_dir(plan_, index);
    std::filesystem::create_directories(dir);
    ChildSpec child;
    child.argv = run_command(o_, plan_, index, self_);
    child.argv.insert(child.argv.end(), {"--threads", std::to_string(threads_)});
    child.log_path = dir + "/log.txt";
    running_[start_child(child)] = {index, Clock::now()};
  }

  // Reports a run that ended and, unless the sweep stopped it, gives it its row in sweep.csv.
  void finish(const Running& r, int exit_status, std::size_t done, Clock::time_point start, bool stopping) {
    RunRecord record;
    record.values = plan_.combinations[r.index];
    read_run_outputs(run_dir(plan_, r.index), record);
    std::string what;
    for (std::size_t k = 0; k < plan_.keys.size(); ++k)
      what += (k ? " " : "") + plan_.keys[k].key + "=" + record.values[k];
    const std::size_t total = plan_.combinations.size();
    std::string line = "firn sweep: [" + std::to_string(done) + "/" + std::to_string(total) + "] run " +
                       std::to_string(r.index + 1) + ", " + what + ": " + record.status;
    if (record.status != "ok")
      line += " (exit status " + std::to_string(exit_status) + ", see " + run_dir(plan_, r.index) + "/log.txt)";
    line += ", " + duration_text(seconds_since(r.start));
    if (done < total && !stopping)
      line += "; ETA " + duration_text(seconds_since(start) / double(done) * double(total - done));
    std::fprintf(stderr, "%s\n", line.c_str());
    if (stopping && record.status == "interrupted") return;  // stopped by the sweep's interrupt: no row
    table_.add(r.index, std::move(record));
    table_.write();
  }

  const Options& o_;
  const Plan& plan_;
  const int threads_;
  const std::string self_ = self_executable();
  SweepTable table_;
  std::map<pid_t, Running> running_;
  sigset_t previous_mask_;
  bool masked_ = false;
};

// Writes the job array and submits it with sbatch; returns the exit status.
int submit_to_slurm(const Options& o, const Plan& plan) {
  const std::string out = std::filesystem::absolute(plan.out).lexically_normal().string();
  Plan absolute = plan;
  absolute.out = out;
  SlurmJob job;
  job.name = "firn_sweep_" + std::filesystem::path(out).filename().string();
  job.slurm_output = out + "/slurm/task_%a.txt";
  job.sbatch_options = o.sbatch;
  const std::string self = self_executable();
  for (std::size_t i = 0; i < plan.combinations.size(); ++i) {
    std::filesystem::create_directories(run_dir(absolute, i));
    job.tasks.push_back({run_command(o, absolute, i, self), run_dir(absolute, i) + "/log.txt"});
  }
  std::filesystem::create_directories(out + "/slurm");
  const std::string script = out + "/slurm/sweep.sbatch";
  write_file_atomically(script, slurm_array_script(job));
  ChildSpec sbatch{{"sbatch", "--parsable", script}, out + "/slurm/sbatch.txt", out, true};
  const int status = wait_child(start_child(sbatch));
  std::string reply = file_text(sbatch.log_path).value_or("");
  while (!reply.empty() && std::isspace(static_cast<unsigned char>(reply.back()))) reply.pop_back();
  if (status != 0) {
    std::fprintf(stderr, "firn sweep: sbatch %s failed (exit status %d%s): %s\n", script.c_str(), status,
                 status == 127 ? ", is Slurm's sbatch installed?" : "", reply.c_str());
    return 1;
  }
  std::fprintf(stderr,
               "firn sweep: submitted Slurm job array %s (%zu runs, %s); when it has finished: firn sweep --collect %s\n",
               reply.substr(0, reply.find(';')).c_str(), plan.combinations.size(), script.c_str(), out.c_str());
  return 0;
}

// firn sweep --collect DIR: sweep.csv and the plots (`plot`, or the sweep's) from the runs that
// have finished.
int collect(const std::string& dir, const std::string& plot) {
  Options o = read_sweep_args(dir);
  if (!plot.empty()) o.plot = plot;
  const Plan plan = make_plan(o);
  SweepTable table(plan);
  std::string missing;
  for (std::size_t i = 0; i < plan.combinations.size(); ++i) {
    if (!std::filesystem::exists(run_dir(plan, i) + "/summary.json")) {
      missing += (missing.empty() ? "" : ", ") + std::to_string(i + 1);
      continue;
    }
    RunRecord record;
    record.values = plan.combinations[i];
    read_run_outputs(run_dir(plan, i), record);
    table.add(i, std::move(record));
  }
  table.write();
  table.plot();
  std::fprintf(stderr, "firn sweep --collect: %zu of %zu runs finished%s; %s/sweep.csv\n", table.size(),
               plan.combinations.size(), missing.empty() ? "" : (" (not yet: run " + missing + ")").c_str(),
               dir.c_str());
  return missing.empty() && table.all_ok() ? 0 : 1;
}

}  // namespace

void add_sweep_command(CLI::App& app) {
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
  sweep->callback([o]() {
    const bool defines_runs = !o->scene.empty() || !o->varies.empty() || !o->sets.empty() || o->preview || !o->at.empty();
    if (o->collect.empty() ? (o->scene.empty() || o->varies.empty()) : defines_runs) {
      std::fprintf(stderr, "firn sweep: %s\n", o->collect.empty()
                                                   ? "give a scene and at least one --vary, or --collect DIR"
                                                   : "--collect DIR reads the sweep's scene and values from DIR/sweep.args; "
                                                     "give no scene, --vary, --set, --at or --preview with it");
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
      std::filesystem::create_directories(plan.out);
      write_file_atomically(plan.out + "/sweep.args", sweep_args_text(*o, plan.scene));
      set_exit_status(o->scheduler == "slurm" ? submit_to_slurm(*o, plan) : Sweep(*o, plan).run());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "firn sweep: %s\n", e.what());
      set_exit_status(1);
    }
  });
}

}  // namespace firn::app
