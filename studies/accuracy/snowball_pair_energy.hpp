// The snowball pair's energy budget (issue 19, items 4 and 7): scenes/snowball_pair.toml, the
// thesis' layered snowballs (its Table 4.2) meeting at 6 m/s each, run to 10 ms with one transfer
// scheme, shape function and precision. The case's error is the budget's residual at the end over
// the initial energy (README.md, "metrics.csv"): what the discretisation dissipated once the
// plastic work is counted, the plastic counterpart of the two spheres' energy loss. Level 0 is the
// scene's --preview, level 1 the scene as written. Per-frame residuals go to the options' log.
#pragma once

#include "engine/verification/verification.hpp"

namespace firn::study {

// Runs the scene from options.scene_folder; throws StabilityError when the run does not end ok.
VerificationCase snowball_pair_energy_case(int level, const VerificationMethod& method,
                                           const VerificationOptions& options);

}  // namespace firn::study
