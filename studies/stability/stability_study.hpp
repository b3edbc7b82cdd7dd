// firn study stability: the numerical stability report of issue 8 (DESIGN.md section 6, problem 6):
//   1. the largest CFL number that runs to the end, per thesis material (a ball thrown into a wall)
//      and per thesis scene at --preview (bisection, stability_cfl.hpp);
//   2. the highest impact speed the layered snowball survives against the wall (stability_impact.hpp);
//   3. nearly incompressible rubber at nu = 0.45, 0.49, 0.499 (and 0.3 for reference),
//      Mooney-Rivlin and neo-Hookean: a squeezed block's outcome, min J and pressure checkerboard
//      (stability_checkerboard.hpp);
//   4. a resting block of hard snow for 1e5 steps: energy drift and creep (stability_long_run.hpp);
//   5. randomised scenes run in bulk through `firn run` (stability_random_runs.hpp).
// Writes DIR/stability.csv (after every row), DIR/stability.md, PNG plots and DIR/scenes/ (the
// study's own scene files); failing random scenes keep their folders under DIR/random/.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "studies/study_options.hpp"

namespace firn::study {

struct StabilityStudyOptions {
  StudyOptions study{false, "out/study/stability", 0};
  std::uint64_t seed = 1;      // of the randomised scenes
  int random = 0;              // randomised scenes; 0: 200, or 20 with --quick
  std::string scenes;          // the thesis' scene files' folder; empty: found by name in shipped_scenes
  std::string shipped_scenes;  // where a scene given by name is looked for (engine/scene/scene_lookup.hpp)
  std::function<void(const std::string& line)> progress;  // one line per check, with the elapsed time
};

// The file of the thesis scene NAME ("snow_bar"). Throws SceneError when a scene looked up by name
// is not found.
std::string thesis_scene(const StabilityStudyOptions& o, const std::string& name);

// Throws SceneError unless every thesis scene the study runs is a file.
void check_thesis_scenes(const StabilityStudyOptions& o);

// Runs the study; returns the exit status: 0, or 1 when a random scene crashed, was refused or
// wrote a NaN. Throws SceneError or std::runtime_error when the study itself fails.
int run_stability_study(const StabilityStudyOptions& o);

}  // namespace firn::study
