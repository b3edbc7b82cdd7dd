// Sub-commands of the `firn` executable. Each registers itself on the CLI11 app and runs from
// its callback; the process exit status is collected in exit_status().
#pragma once

#include <CLI/CLI.hpp>

namespace firn::app {

void add_bench_command(CLI::App& app);
void add_verify_command(CLI::App& app);

// Exit status of the command that ran (0: success, 1: a check failed or the run failed).
int exit_status();
void set_exit_status(int status);

}  // namespace firn::app
