// firn study stability [--quick] [--out DIR] [--threads N] [--backend B] [--seed S] [--random N] [--scenes DIR]
// The numerical stability report (studies/stability/stability_study.hpp): DIR/stability.csv,
// DIR/stability.md, PNG plots and the study's scene files; progress on standard error.
// Exit status: 0, or 1 when a random scene crashed, was refused or wrote a NaN (or the study
// itself failed), 2 for bad options.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "apps/study_options.hpp"
#include "engine/scene/scene_reader.hpp"
#include "studies/stability/stability_study.hpp"

namespace firn::app {

void add_study_stability_command(CLI::App& study_command) {
  auto o = std::make_shared<study::StabilityStudyOptions>();
  CLI::App* cmd = study_command.add_subcommand(
      "stability", "largest stable CFL, impact speed, nearly incompressible rubber, a long run, random scenes");
  add_study_options(*cmd, o->study);
  cmd->add_option("--seed", o->seed, "seed of the randomised scenes")->capture_default_str();
  cmd->add_option("--random", o->random, "number of randomised scenes (default 200, 20 with --quick)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--scenes", o->scenes, "folder of the thesis' scene files (default: found by name like firn run's)");
  cmd->callback([o]() {
    if (!usable_backend(o->study.backend)) return;
    o->shipped_scenes = shipped_scenes();
    o->progress = [](const std::string& line) { std::fprintf(stderr, "firn study stability: %s\n", line.c_str()); };
    try {
      study::check_thesis_scenes(*o);
    } catch (const SceneError& e) {
      std::fprintf(stderr, "firn study stability: %s\n", e.what());
      set_exit_status(2);
      return;
    }
    try {
      std::fprintf(stderr, "firn study stability%s: outputs in %s\n", o->study.quick ? " --quick" : "",
                   o->study.out.c_str());
      set_exit_status(study::run_stability_study(*o));
    } catch (const SceneError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      set_exit_status(1);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "firn study stability: %s\n", e.what());
      set_exit_status(1);
    }
  });
}

}  // namespace firn::app
