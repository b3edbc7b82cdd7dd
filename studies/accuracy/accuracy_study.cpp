#include "studies/accuracy/accuracy_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/stability_guard.hpp"

namespace firn::study {

bool same_method(const VerificationMethod& a, const VerificationMethod& b) {
  return a.transfer == b.transfer && a.shape == b.shape && a.precision == b.precision;
}

std::vector<AccuracyRow> run_accuracy_cases(const AccuracyProblem& problem, const std::vector<int>& levels,
                                            const std::vector<VerificationMethod>& methods,
                                            const VerificationOptions& options,
                                            const std::function<void(const AccuracyRow&)>& on_row) {
  std::vector<AccuracyRow> rows;
  for (const int level : levels)
    for (const VerificationMethod& method : methods) {
      AccuracyRow row;
      row.problem = problem.name;
      row.level = level;
      row.method = method;
      try {
        row.result = problem.run(level, method, options);
      } catch (const StabilityError& e) {
        row.result.error = std::numeric_limits<double>::quiet_NaN();
        row.status = e.what();
      }
      rows.push_back(row);
      if (on_row) on_row(row);
    }
  return rows;
}

void mark_pareto_front(std::vector<AccuracyRow>& rows) {
  std::vector<AccuracyRow*> by_time;
  for (AccuracyRow& r : rows) {
    r.pareto = false;
    if (std::isfinite(r.result.error)) by_time.push_back(&r);
  }
  std::sort(by_time.begin(), by_time.end(), [](const AccuracyRow* a, const AccuracyRow* b) {
    return a->result.seconds < b->result.seconds ||
           (a->result.seconds == b->result.seconds && a->result.error < b->result.error);
  });
  double best = std::numeric_limits<double>::infinity();
  for (AccuracyRow* r : by_time)
    if (r->result.error < best) {
      r->pareto = true;
      best = r->result.error;
    }
}

double observed_order(const std::vector<AccuracyRow>& rows, const VerificationMethod& method) {
  std::vector<const AccuracyRow*> mine;
  for (const AccuracyRow& r : rows)
    if (same_method(r.method, method) && r.result.error > 0 && std::isfinite(r.result.error)) mine.push_back(&r);
  if (mine.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  std::sort(mine.begin(), mine.end(), [](const AccuracyRow* a, const AccuracyRow* b) { return a->level < b->level; });
  const VerificationCase& coarse = mine[mine.size() - 2]->result;
  const VerificationCase& fine = mine.back()->result;
  return std::log(coarse.error / fine.error) / std::log(coarse.dx / fine.dx);
}

}  // namespace firn::study
