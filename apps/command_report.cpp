// firn report DIR: one self-contained HTML page, DIR/report.html, for a run's or a sweep's output
// folder (studies/report/write_report.hpp); `firn run --report` and `firn sweep --report` write
// the same page when they end.
// Exit status: 0 written, 1 a file could not be read or written, 2 DIR is neither kind of folder.
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "apps/commands.hpp"
#include "engine/scene/scene_reader.hpp"
#include "studies/report/write_report.hpp"

namespace firn::app {

int write_report_page(const std::string& dir, const char* program) {
  try {
    const std::string page = report::write_report(
        dir, shipped_scenes(), [program](const std::string& line) { std::fprintf(stderr, "%s: %s\n", program, line.c_str()); });
    std::printf("report in %s\n", page.c_str());
    return 0;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "%s: %s\n", program, e.what());
    return 2;
  } catch (const SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", program, e.what());
    return 1;
  }
}

void add_report_command(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  CLI::App* report = app.add_subcommand("report", "one self-contained HTML page, DIR/report.html, for a run or a sweep");
  report->add_option("dir", *dir, "a run's or a sweep's output folder")->required();
  report->callback([dir]() { set_exit_status(write_report_page(*dir, "firn report")); });
}

}  // namespace firn::app
