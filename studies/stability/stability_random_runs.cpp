#include "studies/stability/stability_random_runs.hpp"

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "engine/output/atomic_file.hpp"
#include "studies/stability/stability_output_scan.hpp"
#include "studies/stability/stability_random_scene.hpp"
#include "studies/sweep/child_process.hpp"
#include "studies/sweep/run_record.hpp"

namespace firn::study {
namespace {

using Clock = std::chrono::steady_clock;

// The log's line holding `needle`, else its last non-empty line.
std::string log_line(const std::string& log, const std::string& needle) {
  std::istringstream in(log);
  std::string line, last;
  while (std::getline(in, line)) {
    if (line.find(needle) != std::string::npos) return line;
    if (!line.empty()) last = line;
  }
  return last;
}

struct Running {
  int index;
  Clock::time_point start;
  RandomScene scene;
};

// Stops the children still running if the bulk run ends by an exception.
struct Children {
  std::map<pid_t, Running> running;
  ~Children() {
    for (const auto& [pid, r] : running) kill(pid, SIGTERM);
    for (const auto& [pid, r] : running) sweep::wait_child(pid);
  }
};

}  // namespace

std::string classify_random_run(int exit_status, const std::string& log, bool non_finite) {
  if (non_finite) return "nan";
  if (exit_status == 0) return "finished";
  if (exit_status == 1 && log.find("stability guard") != std::string::npos) return "guard_stop";
  if (exit_status == 2) return "bad_input";
  return "crash";
}

void run_random_scenes(const RandomRunSettings& s, const std::function<void(const RandomRunResult&)>& on_result) {
  Children children;
  char name[16];
  auto folder = [&](int index) {
    std::snprintf(name, sizeof name, "%04d", index);
    return s.dir + "/" + name;
  };
  int next = 0;
  while (next < s.count || !children.running.empty()) {
    while (next < s.count && int(children.running.size()) < s.jobs) {
      const std::string dir = folder(next);
      make_directories(dir);
      Running r{next, Clock::now(), random_scene(s.seed, next)};
      write_file_atomically(dir + "/scene.toml", r.scene.toml);
      sweep::ChildSpec child;
      child.argv = {s.firn,  "run", dir + "/scene.toml", "--out", dir + "/out", "--threads", "1",
                    "--backend", s.backend};
      child.log_path = dir + "/log.txt";
      children.running[sweep::start_child(child)] = r;
      ++next;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) break;
    const auto it = children.running.find(pid);
    if (it == children.running.end()) continue;
    const Running r = it->second;
    children.running.erase(it);
    const std::string dir = folder(r.index), log = sweep::file_text(dir + "/log.txt").value_or("");
    const std::vector<std::string> bad = non_finite_outputs(dir + "/out");
    RandomRunResult result;
    result.index = r.index;
    result.exit_status = sweep::exit_status_of(status);
    result.outcome = classify_random_run(result.exit_status, log, !bad.empty());
    result.seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
    result.particles_estimate = r.scene.particles_estimate;
    result.scene = r.scene.summary;
    if (!bad.empty()) result.detail = bad.front();
    else if (result.outcome == "guard_stop") result.detail = log_line(log, "stability guard");
    else if (result.outcome != "finished") result.detail = log_line(log, "error");
    if (!result.failed()) std::filesystem::remove_all(dir);
    on_result(result);
  }
}

}  // namespace firn::study
