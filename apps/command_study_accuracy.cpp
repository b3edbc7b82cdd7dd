// firn study accuracy [--quick] [--out DIR] [--threads N] [--backend B] [--problems NAME...] [--scenes DIR]
// Error against run time on the known-answer problems (studies/accuracy/accuracy_study_run.hpp),
// written to DIR (default out/study/accuracy): accuracy.csv, accuracy.md and the plots. Progress
// goes to standard error, one line per case; the count of cases, the time and the files to
// standard output. Exit status: 0, 1 when a plot could not be drawn, 2 for bad options.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "apps/commands.hpp"
#include "apps/study_options.hpp"
#include "studies/accuracy/accuracy_problems.hpp"
#include "studies/accuracy/accuracy_study_run.hpp"

namespace firn::app {

void add_study_accuracy_command(CLI::App& study_command) {
  auto o = std::make_shared<study::AccuracyStudyOptions>();
  CLI::App* accuracy = study_command.add_subcommand(
      "accuracy", "error against run time: every known-answer problem, resolution and method");
  add_study_options(*accuracy, o->study);
  std::vector<std::string> names;
  for (const study::AccuracyProblem& p : study::accuracy_problems()) names.push_back(p.name);
  accuracy->add_option("--problems", o->problems, "problems to run (default: all)")->check(CLI::IsMember(names));
  accuracy->add_option("--scenes", o->scenes,
                       "folder of the shipped scene files (snowball_pair_energy; default: found by name like firn run's)");
  accuracy->callback([o]() {
    if (!usable_backend(o->study.backend)) return;
    if (o->scenes.empty()) o->scenes = shipped_scenes();
    const bool scene_problem = o->problems.empty() || std::find(o->problems.begin(), o->problems.end(),
                                                                "snowball_pair_energy") != o->problems.end();
    if (scene_problem && !std::filesystem::is_regular_file(o->scenes + "/snowball_pair.toml")) {
      std::fprintf(stderr, "firn study accuracy: no snowball_pair.toml in %s (give the scene folder with --scenes)\n",
                   o->scenes.c_str());
      set_exit_status(2);
      return;
    }
    const std::string& dir = o->study.out;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
      std::fprintf(stderr, "firn study: cannot create %s: %s\n", dir.c_str(), ec.message().c_str());
      set_exit_status(2);
      return;
    }
    o->progress = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    const study::AccuracyStudyResult r = study::run_accuracy_study(*o);
    std::printf("cases %zu\nseconds %.1f\ncsv %s/accuracy.csv\nsummary %s/accuracy.md\n", r.cases, r.seconds,
                dir.c_str(), dir.c_str());
    set_exit_status(r.plotted ? 0 : 1);
  });
}

}  // namespace firn::app
