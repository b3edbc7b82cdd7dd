// Sub-commands of the `firn` executable. Each registers itself on the CLI11 app and runs from
// its callback; the process exit status is collected in exit_status().
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace firn::app {

void add_bench_command(CLI::App& app);
void add_verify_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_sweep_command(CLI::App& app);
void add_report_command(CLI::App& app);
void add_study_command(CLI::App& app);
void add_help_command(CLI::App& app);

// firn render OUTDIR ... and firn bench render ... (without the renderer: apps/render_unavailable.cpp).
void add_render_command(CLI::App& app);
void add_bench_render_command(CLI::App& bench);

// Writes DIR/report.html for a run or a sweep (firn report, and --report of firn run and firn
// sweep), saying where on standard output or what failed on standard error as `program`; returns
// the exit status: 0 written, 1 a file could not be read or written, 2 DIR is neither kind of folder.
int write_report_page(const std::string& dir, const char* program);

// Sub-commands of `firn study`.
void add_study_accuracy_command(CLI::App& study_command);
void add_study_stability_command(CLI::App& study_command);

// The folder of the scenes shipped with firn (installed: PREFIX/share/firn/scenes; in the build
// folder: the source tree's scenes/), and the file a SCENE argument names, a shipped scene's name
// included (engine/scene/scene_lookup.hpp; throws SceneError).
std::string shipped_scenes();
std::string scene_path(const std::string& scene);

// Exit status of the command that ran (0: success, 1: a check or the run failed, 2: bad input,
// 130: interrupted).
int exit_status();
void set_exit_status(int status);

}  // namespace firn::app
