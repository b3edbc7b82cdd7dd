// `--backend serial|openmp|cuda` (engine/backend_kind.hpp) for the commands that step simulations:
// run, verify, bench step, sweep and study.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "engine/backend_kind.hpp"

namespace firn::app {

// Adds the option to `command`, storing the name in `name` (default: openmp).
void add_backend_option(CLI::App* command, std::string& name);

// The backend called `name` when it can run here; otherwise prints why in one line ("this build has
// no CUDA backend", "no CUDA device"), sets exit status 2 and returns nothing.
std::optional<BackendKind> usable_backend(const std::string& name);

}  // namespace firn::app
