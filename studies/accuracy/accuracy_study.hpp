// `firn study accuracy`: every known-answer problem at each resolution level with every method,
// error beside run time, so a user can pick the cheapest setting that meets an error target.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "studies/accuracy/accuracy_problems.hpp"

namespace firn::study {

struct AccuracyRow {
  std::string problem;
  int level = 0;
  VerificationMethod method;
  VerificationCase result;    // error NaN when the run stopped
  std::string status = "ok";  // or why the run stopped (the stability guard's message)
  bool pareto = false;        // on the problem's front: no other case is both faster and more accurate

  double particle_steps_per_second() const {
    return result.seconds > 0 ? double(result.particles) * double(result.steps) / result.seconds : 0;
  }
};

// Runs `problem` at each of `levels` (outer loop, coarse first, so an interrupted study keeps whole
// levels) with each method, calling on_row after every case.
std::vector<AccuracyRow> run_accuracy_cases(const AccuracyProblem& problem, const std::vector<int>& levels,
                                            const std::vector<VerificationMethod>& methods,
                                            const VerificationOptions& options,
                                            const std::function<void(const AccuracyRow&)>& on_row = {});

// Sets `pareto` on the rows of one problem: sorted by run time, a case is on the front when its
// error is below that of every faster case.
void mark_pareto_front(std::vector<AccuracyRow>& rows);

// The observed order of the error in dx for one method, log(e1 / e2) / log(dx1 / dx2) over its two
// finest levels with a positive error; NaN with fewer than two.
double observed_order(const std::vector<AccuracyRow>& rows, const VerificationMethod& method);

bool same_method(const VerificationMethod& a, const VerificationMethod& b);

}  // namespace firn::study
