#include "studies/sweep/local_sweep.hpp"

#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "studies/sweep/child_process.hpp"
#include "studies/sweep/finished_runs.hpp"
#include "studies/sweep/run_record.hpp"

namespace firn::sweep {
namespace {

using Clock = std::chrono::steady_clock;

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

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Running {
  std::size_t index;
  Clock::time_point start;
};

class LocalSweep {
 public:
  LocalSweep(const SweepOptions& o, const SweepPlan& plan, const SweepReport& report)
      : o_(o), plan_(plan), report_(report), threads_(std::max(1, cores() / o.jobs)), finished_(plan, report) {}
  // Stops the runs still going if run() ends by an exception.
  ~LocalSweep() {
    for (const auto& [pid, r] : running_) kill(pid, SIGTERM);
    for (const auto& [pid, r] : running_) wait_child(pid);
    if (masked_) sigprocmask(SIG_SETMASK, &previous_mask_, nullptr);
  }

  int run() {
    const std::size_t total = plan_.combinations.size();
    std::filesystem::create_directories(plan_.out + "/runs");
    report_(std::to_string(total) + " runs, " + std::to_string(o_.jobs) + " at a time on " + std::to_string(threads_) +
            " thread" + (threads_ == 1 ? "" : "s") + " each, outputs in " + plan_.out);
    // SIGINT, SIGTERM and SIGCHLD are taken synchronously with sigwaitinfo, so none is missed
    // between launching and waiting; children start with them unblocked.
    sigset_t signals;
    sigemptyset(&signals);
    for (const int s : {SIGINT, SIGTERM, SIGCHLD}) sigaddset(&signals, s);
    sigprocmask(SIG_BLOCK, &signals, &previous_mask_);
    masked_ = true;
    const auto start = Clock::now();
    std::vector<std::size_t> pending;  // the runs to start, in order
    std::size_t next = 0, done = 0;
    for (std::size_t i = 0; i < total; ++i) {
      if (o_.resume && run_state(plan_, i) == RunState::finished) {
        RunRecord record;
        record.values = plan_.combinations[i];
        read_run_outputs(run_dir(plan_, i), record);
        finished_.add(i, std::move(record));
        ++done;
      } else {
        pending.push_back(i);
      }
    }
    started_done_ = done;
    if (o_.resume)
      report_(std::to_string(done) + " finished before, " + std::to_string(pending.size()) + " to resume or run");
    bool interrupted = false;
    while (true) {
      while (!interrupted && next < pending.size() && running_.size() < std::size_t(o_.jobs)) launch(pending[next++]);
      if (running_.empty()) break;
      siginfo_t info;
      const int s = sigwaitinfo(&signals, &info);
      if (s == SIGINT || s == SIGTERM) {
        if (!interrupted) {
          report_("interrupted; stopping " + std::to_string(running_.size()) + " running run" +
                  (running_.size() == 1 ? "" : "s"));
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
    finished_.write();  // also when no run finished
    int status = interrupted ? 130 : 0;
    if (!interrupted) {
      if (!finished_.all_ok()) status = 1;
      finished_.plot();
      // An interrupt during plotting is still one.
      const timespec now{0, 0};
      for (int s; (s = sigtimedwait(&signals, nullptr, &now)) > 0;)
        if (s != SIGCHLD) status = 130;
    }
    sigprocmask(SIG_SETMASK, &previous_mask_, nullptr);
    masked_ = false;
    report_(std::to_string(finished_.size()) + " of " + std::to_string(total) + " runs finished in " +
            duration_text(seconds_since(start)) + "; " + plan_.out + "/sweep.csv");
    return status;
  }

 private:
  void launch(std::size_t index) {
    const std::string dir = run_dir(plan_, index);
    std::filesystem::create_directories(dir);
    ChildSpec child;
    const bool resume = o_.resume && run_state(plan_, index) == RunState::resumable;
    child.argv = resume ? resume_command(o_, plan_, index, self_) : run_command(o_, plan_, index, self_);
    child.append_log = resume;
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
    std::string line = "[" + std::to_string(done) + "/" + std::to_string(total) + "] run " +
                       std::to_string(r.index + 1) + ", " + what + ": " + record.status;
    if (record.status != "ok")
      line += " (exit status " + std::to_string(exit_status) + ", see " + run_dir(plan_, r.index) + "/log.txt)";
    line += ", " + duration_text(seconds_since(r.start));
    if (done < total && !stopping && done > started_done_)
      line += "; ETA " + duration_text(seconds_since(start) / double(done - started_done_) * double(total - done));
    report_(line);
    if (stopping && record.status == "interrupted") return;  // stopped by the sweep's interrupt: no row
    finished_.add(r.index, std::move(record));
    finished_.write();
  }

  const SweepOptions& o_;
  const SweepPlan& plan_;
  const SweepReport& report_;
  const int threads_;
  const std::string self_ = self_executable();
  FinishedRuns finished_;
  std::map<pid_t, Running> running_;
  std::size_t started_done_ = 0;  // runs that had finished before this sweep started (--resume)
  sigset_t previous_mask_;
  bool masked_ = false;
};

}  // namespace

int run_local_sweep(const SweepOptions& o, const SweepPlan& plan, const SweepReport& report) {
  return LocalSweep(o, plan, report).run();
}

}  // namespace firn::sweep
