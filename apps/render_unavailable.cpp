// The renderer's entry points in a build without viz/ (its headers were missing at configure
// time), a sweep's contact sheets among them: each says so.
#include <cstdio>
#include <stdexcept>

#include "apps/commands.hpp"
#include "studies/report/contact_sheet.hpp"
#include "viz/run_rendering.hpp"

namespace firn {
namespace {

const char* const kMissing =
    "firn was built without the renderer (install the packages of `make deps` and reconfigure)";

void add_unavailable(CLI::App& parent, const char* name, const char* what) {
  CLI::App* c = parent.add_subcommand(name, what);
  c->allow_extras();
  c->callback([] {
    std::fprintf(stderr, "%s\n", kMissing);
    app::set_exit_status(2);
  });
}

}  // namespace

viz::RunRendering viz::start_run_rendering(const SceneSpec&, const std::string&, bool, const std::string&, bool, int) {
  throw std::runtime_error(kMissing);
}

std::vector<std::string> report::write_contact_sheets(const sweep::SweepPlan&) { throw std::runtime_error(kMissing); }

void app::add_render_command(CLI::App& app) { add_unavailable(app, "render", "re-render a finished run (not built)"); }
void app::add_bench_render_command(CLI::App& bench) {
  add_unavailable(bench, "render", "time the renderer (not built)");
}

}  // namespace firn
