// Known-answer problems (DESIGN.md section 6), shared by `firn verify` and the test suite. Each
// problem runs at one or more levels and reports an error against its stated bound, in double
// precision on the OpenMP backend.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace firn {

struct VerificationRow {
  std::string problem;
  int level;
  double dx;
  int particles_per_cell;  // per axis
  long steps;
  double error;
  double bound;
  double seconds;
  bool passed() const { return error <= bound; }  // false for NaN
};

struct VerificationOptions {
  int threads = 0;             // 0: all cores
  std::ostream* log = nullptr;  // histories (energy per transfer scheme, ...) go here
};

// Names of the problems, in the order `firn verify` runs them.
std::vector<std::string> verification_problems();

// Problems too slow for the default run and the test suite, run only when named.
std::vector<std::string> verification_problems_on_request();

// Runs one problem; throws std::invalid_argument for an unknown name.
std::vector<VerificationRow> run_verification(const std::string& problem, const VerificationOptions& options);

// Axially vibrating bar (Bardenhagen 2002; Tielen et al. 2017): error of the free end's
// displacement against v0/w sin(wt) sin(beta x), relative to the amplitude, over one period.
std::vector<VerificationRow> verify_vibrating_bar(const VerificationOptions& options);

// Manufactured solution (Wallstedt and Guilkey 2008): RMS displacement error per level, and the
// observed convergence order as a row whose error is the shortfall from second order.
std::vector<VerificationRow> verify_manufactured_solution(const VerificationOptions& options);

// Two elastic spheres colliding (Sulsky et al. 1994, in 3D): relative drift of total momentum per
// transfer scheme; the energy history goes to the log.
std::vector<VerificationRow> verify_two_spheres(const VerificationOptions& options);

// Block sliding down a 30-degree incline with Coulomb friction (incline_sliding.cpp): relative
// error of the centre of mass's acceleration against g (sin theta - mu cos theta).
std::vector<VerificationRow> verify_incline_sliding(const VerificationOptions& options);

// Solid cylinder on a 45-degree incline (incline_rolling.cpp) at R / dx = 10: the rolling
// acceleration against 2/3 g sin theta, and the slip ratio at mu = 1.25 and 0.75 times tan(theta) / 3
// (rolls, slides). The _fine variant runs R / dx = 20 and 40 (on request only).
std::vector<VerificationRow> verify_incline_rolling(const VerificationOptions& options);
std::vector<VerificationRow> verify_incline_rolling_fine(const VerificationOptions& options);

// Material-point driver (engine/material_driver.hpp) for one constitutive model ("hyperelastic_plastic",
// "snow_stomakhin", "mooney_rivlin"): closed forms, yield surface and J_P bookkeeping after every
// return, sub-stepped references, objectivity. One row per check.
std::vector<VerificationRow> verify_material_driver(const std::string& model);

}  // namespace firn
