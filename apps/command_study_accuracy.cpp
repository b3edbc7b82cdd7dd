// firn study accuracy [--quick] [--out DIR] [--threads N] [--backend B] [--problems NAME...]
// Runs every known-answer problem at each of its resolution levels with every method (transfer
// scheme x shape function x precision, at the problem's fixed CFL number) and writes to DIR
// (default out/study/accuracy):
//   accuracy.csv            one row per case (error, run time, particle-steps/s, Pareto flag),
//                           rewritten after every case so an interrupted study keeps what it ran;
//   accuracy.md             observed orders and the Pareto front per problem;
//   PROBLEM.png             error against dx and against run time (gnuplot; .dat and .gp beside it);
//   two_spheres_energy.png  total energy against time for APIC, PIC and FLIP.
// Progress goes to standard error, one line per case.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "apps/study_options.hpp"
#include "engine/output/atomic_file.hpp"
#include "studies/accuracy/accuracy_plot.hpp"
#include "studies/accuracy/accuracy_report.hpp"

namespace firn::app {
namespace {

using namespace firn::study;

struct AccuracyOptions {
  StudyOptions study{false, "out/study/accuracy", 0};
  std::vector<std::string> problems;  // empty: all
};

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

void run_accuracy_study(const AccuracyOptions& o) {
  std::vector<AccuracyProblem> problems;
  for (const AccuracyProblem& p : accuracy_problems())
    if (o.problems.empty() || std::find(o.problems.begin(), o.problems.end(), p.name) != o.problems.end())
      problems.push_back(p);
  const std::vector<VerificationMethod> methods = all_methods();
  std::size_t total = 0;
  for (const AccuracyProblem& p : problems) total += (o.study.quick ? p.quick_levels : p.levels).size() * methods.size();

  const std::string& dir = o.study.out;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    std::fprintf(stderr, "firn study: cannot create %s: %s\n", dir.c_str(), ec.message().c_str());
    set_exit_status(2);
    return;
  }
  VerificationOptions options;
  options.backend = backend_named(o.study.backend);
  options.threads = o.study.threads;
  const auto start = std::chrono::steady_clock::now();
  std::vector<AccuracyRow> rows;
  bool plotted = true;
  for (const AccuracyProblem& p : problems) {
    const std::size_t first = rows.size();
    run_accuracy_cases(p, o.study.quick ? p.quick_levels : p.levels, methods, options, [&](const AccuracyRow& r) {
      rows.push_back(r);
      write_file_atomically(dir + "/accuracy.csv", accuracy_csv(rows));
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "[%zu/%zu] %s level %d %s: error %.3g, %.2f s (%.0f s elapsed)%s%s\n", rows.size(), total,
                   r.problem.c_str(), r.level, method_name(r.method).c_str(), r.result.error, r.result.seconds,
                   elapsed, r.status == "ok" ? "" : ": ", r.status == "ok" ? "" : r.status.c_str());
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
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("cases %zu\nseconds %.1f\ncsv %s/accuracy.csv\nsummary %s/accuracy.md\n", rows.size(), elapsed,
              dir.c_str(), dir.c_str());
  set_exit_status(plotted ? 0 : 1);
}

}  // namespace

void add_study_accuracy_command(CLI::App& study) {
  auto o = std::make_shared<AccuracyOptions>();
  CLI::App* accuracy =
      study.add_subcommand("accuracy", "error against run time: every known-answer problem, resolution and method");
  add_study_options(*accuracy, o->study);
  std::vector<std::string> names;
  for (const AccuracyProblem& p : accuracy_problems()) names.push_back(p.name);
  accuracy->add_option("--problems", o->problems, "problems to run (default: all)")->check(CLI::IsMember(names));
  accuracy->callback([o]() {
    if (usable_backend(o->study.backend)) run_accuracy_study(*o);
  });
}

}  // namespace firn::app
