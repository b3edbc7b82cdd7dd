// A run's checkpoint, OUT_DIR/checkpoint.firn (DESIGN.md section 5; `firn run --checkpoint-every`,
// `firn run --resume OUT_DIR`): everything a resumed run needs to end exactly as the
// uninterrupted one, in one file written atomically and synced to disk.
//
// Layout: the magic "FIRNCKPT", the format version, firn's version (engine/version.hpp), a 64-bit
// FNV-1a digest of the resolved scene (scene.resolved.toml), the run's progress (the frame it is
// heading for, metrics.csv's text so far, the energy at frame 0, the work counted for
// summary.json), then the engine state (Simulation::save_state, then the conveyor's), and last an
// FNV-1a checksum of all that. A file whose magic, format, firn version, scene or checksum differ is
// refused with a message that says which.
#pragma once

#include <cstdint>
#include <string>

#include "engine/state_stream.hpp"

namespace firn {

struct RunCheckpoint {
  int next_frame = 1;          // the output frame the run was stepping towards
  std::string metrics;         // metrics.csv up to frame next_frame - 1
  double initial_energy = 0;   // kinetic + elastic at frame 0 (the energy residual's reference)
  double particle_steps = 0;   // summary.json's counters so far
  double step_seconds = 0;
  std::string engine_state;    // Simulation::save_state, then the conveyor's
};

// The interval of --checkpoint-every ("50ms", "0.05"), in simulated seconds; throws
// std::invalid_argument naming the option when the text is not a positive time.
double checkpoint_interval(const std::string& text);

// OUT_DIR/checkpoint.firn
std::string checkpoint_path(const std::string& out_dir);

// FNV-1a (64 bits) over a text: the identity of a resolved scene, and a checkpoint's checksum.
std::uint64_t text_digest(const std::string& text);

// Writes the checkpoint of a run of the scene whose resolved text is `resolved_toml`, atomically
// and durably; throws std::runtime_error on an I/O failure.
void write_checkpoint(const std::string& path, const std::string& resolved_toml, const RunCheckpoint& c);

// Reads a checkpoint and checks that this firn wrote it for this scene; throws CheckpointError
// with the reason (missing, not a checkpoint, another format, another firn, another scene, truncated).
RunCheckpoint read_checkpoint(const std::string& path, const std::string& resolved_toml);

}  // namespace firn
