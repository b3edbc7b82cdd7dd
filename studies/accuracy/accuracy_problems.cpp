#include "studies/accuracy/accuracy_problems.hpp"

#include "studies/accuracy/snowball_pair_energy.hpp"

namespace firn::study {

const std::vector<AccuracyProblem>& accuracy_problems() {
  static const std::vector<AccuracyProblem> problems = {
      {"vibrating_bar", "largest free-end displacement error over one period / amplitude", 2,
       "second order with the clamped mirror end for APIC with cubic B-splines; quadratic ones level off near "
       "2.6e-4 (the quadrature of 2 particles per cell per axis), and PIC's and FLIP's dissipation is first order "
       "(engine/verification/vibrating_bar.cpp)",
       {0, 1, 2, 3}, {0, 1}, vibrating_bar_case},
      {"manufactured_solution", "largest RMS displacement error / amplitude", 2,
       "second order: quadratic and cubic B-splines with particles per cell refined along with dx "
       "(Wallstedt and Guilkey 2008's sin(2 pi X), its stressed ends clamped by mirror planes)",
       {0, 1, 2, 3}, {0, 1, 2}, manufactured_solution_case},
      {"two_spheres", "relative loss of total (kinetic + elastic) energy after the elastic collision", 0,
       "no order is stated: the loss is the transfer's numerical dissipation, large for PIC and small for APIC "
       "(Jiang et al. 2015) and FLIP",
       {0, 1, 2}, {0, 1},
       [](int level, const VerificationMethod& m, const VerificationOptions& o) {
         return two_spheres_case(level, m, o).run;
       }},
      {"incline_sliding", "|a / (g (sin t - mu cos t)) - 1| of the block's acceleration", 0,
       "none: contact nodes that stick (|v_t| < mu |v_n|) set a floor near 0.13% "
       "(engine/verification/incline_sliding.cpp)",
       {0, 1, 2}, {0, 1}, incline_sliding_case},
      {"incline_rolling", "|a / (2/3 g sin t) - 1| of the rolling cylinder's acceleration", 0,
       "none stated: on the pooled ground the error falls (1.3%, 0.6% at R/dx 10, 20 with APIC; 0.25% at 40 in firn "
       "verify) and changes sign; PIC and FLIP lose the spin in the transfer (engine/verification/incline_rolling.cpp)",
       {0, 1}, {0}, incline_rolling_case},
      {"incline_sliding_cylinder", "|a / (g (sin t - mu cos t)) - 1| of the sliding cylinder's acceleration", 0,
       "none stated: on the pooled ground the friction is mu N and the error is under 0.2% at R/dx 10-40 with APIC "
       "(engine/verification/incline_rolling.cpp)",
       {0, 1}, {0}, incline_sliding_cylinder_case},
      {"snowball_pair_energy",
       "the energy budget's residual / initial energy at 10 ms of the thesis' snowball pair (plastic work counted)", 0,
       "no order is stated: like the two spheres' loss, the residual is the transfer's numerical dissipation; level 0 "
       "is the scene's --preview (studies/accuracy/snowball_pair_energy.cpp)",
       {0, 1}, {0}, snowball_pair_energy_case},
  };
  return problems;
}

std::vector<VerificationMethod> all_methods() {
  std::vector<VerificationMethod> methods;
  for (const Transfer t : {Transfer::apic, Transfer::pic, Transfer::flip})
    for (const Shape s : {Shape::quadratic, Shape::cubic})
      for (const Precision p : {Precision::double_, Precision::single}) methods.push_back({t, s, p});
  return methods;
}

}  // namespace firn::study
