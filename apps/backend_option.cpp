#include "apps/backend_option.hpp"

#include <cstdio>

#include "apps/commands.hpp"

namespace firn::app {

void add_backend_option(CLI::App* command, std::string& name) {
  command->add_option("--backend", name, "where the step runs: serial, openmp or cuda")
      ->check(CLI::IsMember({"serial", "openmp", "cuda"}))
      ->capture_default_str();
}

std::optional<BackendKind> usable_backend(const std::string& name) {
  const BackendKind kind = backend_named(name);
  const std::string why = backend_unavailable(kind);
  if (why.empty()) return kind;
  std::fprintf(stderr, "%s\n", why.c_str());
  set_exit_status(2);
  return std::nullopt;
}

}  // namespace firn::app
