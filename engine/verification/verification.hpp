// Known-answer problems (DESIGN.md section 6), shared by `firn verify` and the test suite. Each
// problem runs at one or more levels and reports an error against its stated bound, on the chosen
// backend (OpenMP by default) with the default method (method.hpp). The *_case functions run one
// level with any method, for `firn study accuracy`.
#pragma once

#include <cstddef>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "engine/backend_kind.hpp"
#include "engine/verification/method.hpp"

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
  std::size_t particles = 0;
  bool passed() const { return error <= bound; }  // false for NaN
};

struct VerificationOptions {
  BackendKind backend = BackendKind::openmp;  // available here (backend_unavailable)
  int threads = 0;                            // OpenMP threads, 0: all cores
  std::ostream* log = nullptr;                // histories (energy per transfer scheme, ...) go here
  std::string scene_folder;                   // the shipped scenes, for problems that run a scene file
};

// One run of a problem at one resolution level. `error` is the quantity the problem's comment
// defines; `seconds` is the wall time of the steps alone.
struct VerificationCase {
  double dx = 0;
  int particles_per_cell = 0;  // per axis
  std::size_t particles = 0;
  long steps = 0;
  double error = 0;
  double seconds = 0;
};

// Names of the problems, in the order `firn verify` runs them.
std::vector<std::string> verification_problems();

// Problems too slow for the default run and the test suite, run only when named.
std::vector<std::string> verification_problems_on_request();

// Runs one problem; throws std::invalid_argument for an unknown name.
std::vector<VerificationRow> run_verification(const std::string& problem, const VerificationOptions& options);

// Axially vibrating bar (Bardenhagen 2002; Tielen et al. 2017): error of the free end's
// displacement against v0/w sin(wt) sin(beta x), relative to the amplitude, over one period.
// Level l: dx = L / (50 * 2^l), 2 particles per cell.
std::vector<VerificationRow> verify_vibrating_bar(const VerificationOptions& options);
VerificationCase vibrating_bar_case(int level, const VerificationMethod& method, const VerificationOptions& options);

// Manufactured solution (Wallstedt and Guilkey 2008): RMS displacement error per level, and the
// observed convergence order as a row whose error is the shortfall from second order.
// Level l: dx = 1 / (8 * 2^l), 2 + l particles per cell.
std::vector<VerificationRow> verify_manufactured_solution(const VerificationOptions& options);
VerificationCase manufactured_solution_case(int level, const VerificationMethod& method,
                                            const VerificationOptions& options);

// Two elastic spheres colliding (Sulsky et al. 1994, in 3D): relative drift of total momentum per
// transfer scheme at dx = 1/32; the energy history goes to the log. A case at level l has
// dx = 1 / (16 * 2^l); its error is the relative loss of total energy, and `history` (if set) gets
// (t, kinetic, elastic) after every step.
std::vector<VerificationRow> verify_two_spheres(const VerificationOptions& options);
using EnergyHistory = std::function<void(double t, double kinetic, double elastic)>;
struct TwoSpheresCase {
  VerificationCase run;
  double momentum_drift = 0;
};
TwoSpheresCase two_spheres_case(int level, const VerificationMethod& method, const VerificationOptions& options,
                                const EnergyHistory& history = {});

// Block sliding down a 30-degree incline with Coulomb friction (incline_sliding.cpp): relative
// error of the centre of mass's acceleration against g (sin theta - mu cos theta), at dx = 0.01
// (a case at level l has dx = 0.02 / 2^l).
std::vector<VerificationRow> verify_incline_sliding(const VerificationOptions& options);
VerificationCase incline_sliding_case(int level, const VerificationMethod& method, const VerificationOptions& options);

// Solid cylinder on a 45-degree incline (incline_rolling.cpp) at R / dx = 10: the rolling
// acceleration against 2/3 g sin theta, and the slip ratio at mu = 1.25 and 0.75 times tan(theta) / 3
// (rolls, slides). The _fine variant runs R / dx = 20 and 40 (on request only).
std::vector<VerificationRow> verify_incline_rolling(const VerificationOptions& options);
std::vector<VerificationRow> verify_incline_rolling_fine(const VerificationOptions& options);
// The rolling run alone at R / dx = 10 * 2^level; error |a / (2/3 g sin theta) - 1|.
VerificationCase incline_rolling_case(int level, const VerificationMethod& method, const VerificationOptions& options);
// The sliding run alone (mu = 0.75 tan(theta) / 3) at R / dx = 10 * 2^level; error
// |a / (g (sin theta - mu cos theta)) - 1|.
VerificationCase incline_sliding_cylinder_case(int level, const VerificationMethod& method,
                                               const VerificationOptions& options);

// Material-point driver (material_driver.hpp) for one constitutive model ("hyperelastic_plastic",
// "snow_stomakhin", "mooney_rivlin", "snow_cam_clay"): closed forms, yield surface and J_P bookkeeping after every
// return, sub-stepped references, objectivity. One row per check.
std::vector<VerificationRow> verify_material_driver(const std::string& model);

}  // namespace firn
