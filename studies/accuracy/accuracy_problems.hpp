// The known-answer problems of `firn study accuracy` (DESIGN.md section 6), each with the levels
// of resolution it is swept over and the convergence order theory leads one to expect.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "engine/verification/verification.hpp"

namespace firn::study {

struct AccuracyProblem {
  std::string name;
  std::string error;       // what the error measures
  double expected_order;   // of the error in dx; 0 where none is expected (see `why`)
  std::string why;         // the reason for that order, for the report
  std::vector<int> levels;        // the full study's, coarse to fine
  std::vector<int> quick_levels;  // --quick's
  std::function<VerificationCase(int level, const VerificationMethod&, const VerificationOptions&)> run;
};

const std::vector<AccuracyProblem>& accuracy_problems();

// Every combination of transfer scheme (APIC/MLS, PIC, FLIP blend), shape function (quadratic,
// cubic) and precision (float, double), APIC/quadratic/double first.
std::vector<VerificationMethod> all_methods();

}  // namespace firn::study
