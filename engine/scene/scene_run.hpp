// Runs a loaded scene to its end time and writes the outputs of DESIGN.md section 5 under the
// output folder: scene.resolved.toml, metrics.csv (one row per frame), particles/NNNNN.vtp and
// summary.json. Every file is written atomically; metrics.csv is rewritten at each frame, so it is
// complete up to the last frame whatever happens. A stability-guard stop, an interrupt or an I/O
// failure ends the run with summary.json saying why.
#pragma once

#include <atomic>
#include <functional>
#include <string>

#include "engine/backend_kind.hpp"
#include "engine/output/run_summary.hpp"
#include "engine/scene/frame_description.hpp"
#include "engine/scene/scene_reader.hpp"

namespace firn {

struct RunProgress {
  double time, end_time;
  long steps;
  int frame, frames;
  double step_seconds;  // spent in the step loop so far
};

struct RunOptions {
  std::string out_dir;
  BackendKind backend = BackendKind::openmp;        // available here (backend_unavailable)
  int threads = 0;                                  // OpenMP threads, 0: all cores
  const std::atomic<bool>* interrupt = nullptr;     // set from a signal handler to stop between steps
  std::function<void(const RunProgress&)> progress;  // called after every step
  // Called at every output frame after its files are written (e.g. the renderer); an exception
  // from it ends the run as "failed".
  std::function<void(const FrameDescription&)> on_frame;
  bool rest_positions = false;  // keep x0, the rest positions (surface reconstruction anchors to them)
  // Checkpoints (engine/scene/checkpoint.hpp) to OUT_DIR/checkpoint.firn: at the first output frame
  // at or after every multiple of this many simulated seconds (0: none), and then also at a
  // stability-guard stop or a failure (the last frame's state, kept in memory). An interrupt
  // always writes one, of the state between the two steps where it stopped.
  double checkpoint_every = 0;
  // Continue the run in out_dir from its checkpoint: the scene must be the one the run wrote
  // (scene.resolved.toml); metrics.csv is cut back to the checkpoint's rows and grows from there.
  bool resume = false;
  // Time every launch of the step loop (backend::LaunchProfile; not the frames' diagnostics) into
  // RunSummary::launches.
  bool profile = false;
};

// Builds the scene (throws SceneError before anything is written if a body has no particles, and
// CheckpointError if a checkpoint to resume is missing or not this run's), then runs it. The summary's status says how it ended; its state_hash is that of the final state.
RunSummary run_scene(const LoadedScene& scene, const RunOptions& options);

}  // namespace firn
