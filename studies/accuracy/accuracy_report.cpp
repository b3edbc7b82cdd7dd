#include "studies/accuracy/accuracy_report.hpp"

#include <algorithm>
#include <cmath>

#include "studies/sweep/csv.hpp"

namespace firn::study {

using sweep::csv_field;
using sweep::csv_number;
using sweep::formatted;

std::string accuracy_csv(const std::vector<AccuracyRow>& rows) {
  std::string s =
      "problem,level,dx,particles_per_cell,transfer,shape,precision,particles,steps,error,seconds,"
      "particle_steps_per_second,pareto,status\n";
  for (const AccuracyRow& r : rows) {
    const VerificationCase& c = r.result;
    s += csv_field(r.problem) + "," + std::to_string(r.level) + "," + csv_number(c.dx) + "," +
         std::to_string(c.particles_per_cell) + "," + transfer_name(r.method.transfer) + "," +
         shape_name(r.method.shape) + "," + precision_name(r.method.precision) + "," + std::to_string(c.particles) +
         "," + std::to_string(c.steps) + "," + csv_number(c.error) + "," + csv_number(c.seconds) + "," +
         csv_number(r.particle_steps_per_second()) + "," + (r.pareto ? "1" : "0") + "," + csv_field(r.status) + "\n";
  }
  return s;
}

std::string accuracy_summary(const std::vector<AccuracyProblem>& problems, const std::vector<AccuracyRow>& rows,
                             const std::string& energy_loss_line) {
  std::string s = "# Accuracy against run time\n\nEvery case: `accuracy.csv`. Plots: `PROBLEM.png` (left: error "
                  "against dx with the expected order as a dashed line; right: error against run time with the "
                  "Pareto front).\n";
  for (const AccuracyProblem& problem : problems) {
    std::vector<AccuracyRow> mine;
    for (const AccuracyRow& r : rows)
      if (r.problem == problem.name) mine.push_back(r);
    if (mine.empty()) continue;
    s += "\n## " + problem.name + "\n\nError: " + problem.error + ". Expected order: " +
         (problem.expected_order > 0 ? csv_number(problem.expected_order) : std::string("none")) + "; " +
         problem.why + ".\n\n";
    s += "| method | observed order (two finest levels) | error at the finest level | run time there (s) |\n"
         "|---|---|---|---|\n";
    for (const VerificationMethod& m : all_methods()) {
      const AccuracyRow* finest = nullptr;
      for (const AccuracyRow& r : mine)
        if (same_method(r.method, m) && (!finest || r.level > finest->level)) finest = &r;
      if (!finest) continue;
      const double order = observed_order(mine, m);
      s += "| " + method_name(m) + " | " + (std::isnan(order) ? std::string("-") : formatted("%.2f", order)) + " | " +
           (finest->status == "ok" ? formatted("%.3g", finest->result.error) : "stopped") + " | " +
           formatted("%.2f", finest->result.seconds) + " |\n";
    }
    std::vector<const AccuracyRow*> front;
    for (const AccuracyRow& r : mine)
      if (r.pareto) front.push_back(&r);
    std::sort(front.begin(), front.end(),
              [](const AccuracyRow* a, const AccuracyRow* b) { return a->result.seconds < b->result.seconds; });
    s += "\nPareto front, cheapest first (the cheapest setting meeting an error target is the first row below it):\n\n"
         "| run time (s) | error | level | dx | method |\n|---|---|---|---|---|\n";
    for (const AccuracyRow* r : front)
      s += "| " + formatted("%.3f", r->result.seconds) + " | " + formatted("%.3g", r->result.error) + " | " +
           std::to_string(r->level) + " | " + csv_number(r->result.dx) + " | " + method_name(r->method) + " |\n";
    std::size_t stopped = 0;
    for (const AccuracyRow& r : mine) stopped += r.status != "ok";
    if (stopped) s += "\n" + std::to_string(stopped) + " case(s) stopped; see the status column of accuracy.csv.\n";
    if (problem.name == "two_spheres" && !energy_loss_line.empty()) s += "\n" + energy_loss_line + "\n";
  }
  return s;
}

}  // namespace firn::study
