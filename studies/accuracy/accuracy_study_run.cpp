#include "studies/accuracy/accuracy_study_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "engine/backend_kind.hpp"
#include "engine/output/atomic_file.hpp"
#include "studies/accuracy/accuracy_plot.hpp"
#include "studies/accuracy/accuracy_report.hpp"

namespace firn::study {
namespace {

// The two spheres' total energy per transfer scheme at dx = 1/32 (quadratic, double), and a line
// for the summary with each scheme's loss.
std::vector<EnergySeries> energy_histories(const VerificationOptions& options, std::string& loss_line) {
  std::vector<EnergySeries> series;
  loss_line = "Energy lost by t = 4 s at dx = 1/32 (quadratic, double; `two_spheres_energy.png`):";
  for (const Transfer t : {Transfer::apic, Transfer::pic, Transfer::flip}) {
    VerificationMethod method;
    method.transfer = t;
    EnergySeries e;
    e.title = transfer_name(t);
    two_spheres_case(1, method, options, [&e](double time, double kinetic, double elastic) {
      e.time.push_back(time);
      e.total.push_back(kinetic + elastic);
    });
    char text[64];
    std::snprintf(text, sizeof text, " %s %.1f%%", e.title.c_str(), 100 * (1 - e.total.back() / e.total.front()));
    loss_line += text;
    series.push_back(std::move(e));
  }
  loss_line += ".";
  return series;
}

bool draw(const std::string& dir, const std::string& name, const sweep::PlotFiles& files) {
  return sweep::draw_plot_or_warn("firn study accuracy", dir, name, files) == sweep::PlotStatus::drawn;
}

}  // namespace

AccuracyStudyResult run_accuracy_study(const AccuracyStudyOptions& o) {
  std::vector<AccuracyProblem> problems;
  for (const AccuracyProblem& p : accuracy_problems())
    if (o.problems.empty() || std::find(o.problems.begin(), o.problems.end(), p.name) != o.problems.end())
      problems.push_back(p);
  const std::vector<VerificationMethod> methods = all_methods();
  std::size_t total = 0;
  for (const AccuracyProblem& p : problems) total += (o.study.quick ? p.quick_levels : p.levels).size() * methods.size();

  const std::string& dir = o.study.out;
  VerificationOptions options;
  options.backend = backend_named(o.study.backend);
  options.threads = o.study.threads;
  options.scene_folder = o.scenes;
  const auto start = std::chrono::steady_clock::now();
  std::vector<AccuracyRow> rows;
  bool plotted = true;
  for (const AccuracyProblem& p : problems) {
    const std::size_t first = rows.size();
    run_accuracy_cases(p, o.study.quick ? p.quick_levels : p.levels, methods, options, [&](const AccuracyRow& r) {
      rows.push_back(r);
      write_file_atomically(dir + "/accuracy.csv", accuracy_csv(rows));
      if (!o.progress) return;
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      char line[256];
      std::snprintf(line, sizeof line, "[%zu/%zu] %s level %d %s: error %.3g, %.2f s (%.0f s elapsed)", rows.size(),
                    total, r.problem.c_str(), r.level, method_name(r.method).c_str(), r.result.error, r.result.seconds,
                    elapsed);
      o.progress(line + (r.status == "ok" ? "" : ": " + r.status));
    });
    std::vector<AccuracyRow> mine(rows.begin() + std::ptrdiff_t(first), rows.end());
    mark_pareto_front(mine);
    std::copy(mine.begin(), mine.end(), rows.begin() + std::ptrdiff_t(first));
    plotted = draw(dir, p.name, accuracy_plot(p, mine)) && plotted;
  }
  std::string loss_line;
  const bool spheres = std::any_of(problems.begin(), problems.end(),
                                   [](const AccuracyProblem& p) { return p.name == "two_spheres"; });
  if (spheres) plotted = draw(dir, "two_spheres_energy", energy_history_plot(energy_histories(options, loss_line))) && plotted;
  write_file_atomically(dir + "/accuracy.csv", accuracy_csv(rows));
  write_file_atomically(dir + "/accuracy.md", accuracy_summary(problems, rows, loss_line));
  return {rows.size(), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), plotted};
}

}  // namespace firn::study
