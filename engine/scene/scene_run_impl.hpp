// The scene run of engine/scene/scene_run.hpp for any backend: included by one translation unit
// per backend (scene_run.cpp for OpenMP, scene_run_serial.cpp, scene_run_cuda.cu). The CUDA one
// compiles its backend's step; the serial and OpenMP steps are compiled once, in
// engine/simulation_serial.cpp and engine/simulation_openmp.cpp.
#pragma once

#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <optional>
#include <type_traits>

#include "engine/output/atomic_file.hpp"
#include "engine/openmp_wait.hpp"
#include "engine/output/frame_files.hpp"
#include "engine/output/vtp_writer.hpp"
#include "engine/scene/checkpoint.hpp"
#include "engine/scene/scene_materials.hpp"
#include "engine/scene/scene_metrics.hpp"
#include "engine/scene/scene_run.hpp"
#include "engine/scene/scene_stepper.hpp"
#include "kernels/backend/launch_profile.hpp"
#include "kernels/backend/memory_space.hpp"

namespace firn {
namespace scene_run_detail {

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

template <class T, class Backend>
FrameDescription describe_frame(const Simulation<T, Backend>& sim, const SceneMaterials& materials,
                                const ParticleView<T>& view, int frame, const std::vector<Collider<double>>& colliders) {
  FrameDescription f;
  f.frame = frame;
  f.time = sim.time();
  if constexpr (std::is_same_v<T, float>) f.particles_float = &view;
  else f.particles_double = &view;
  for (int m = 0; m < int(sim.material_count()); ++m) {
    const ParticleRange r = sim.material_range(m);
    f.materials.push_back({r.begin, r.end, materials.table_of(m)});
  }
  f.colliders = &colliders;
  return f;
}

template <class T, class Backend>
RunSummary run(const LoadedScene& loaded, const RunOptions& options, const Backend& backend) {
  const auto wall0 = Clock::now();
  const SceneSpec& scene = loaded.spec;
  std::optional<SceneMetrics<T, Backend>> scene_metrics;
  SceneStepperOptions<T, Backend> stepper_options;
  stepper_options.rest_positions = options.rest_positions;
  stepper_options.before_prepare = [&](Simulation<T, Backend>& sim, const BuiltScene& built, const Conveyor* conveyor) {
    scene_metrics.emplace(scene, built, conveyor);
    scene_metrics->prepare(sim);
    sim.enable_energy_budget();
  };
  SceneStepper<T, Backend> stepper(scene, backend, stepper_options);
  const SceneMaterials materials(scene);  // the scene's table of each engine material, for frames
  Simulation<T, Backend>& sim = stepper.sim();
  backend::LaunchProfile profile;  // the step loop's launches alone (not the frames' diagnostics)

  RunSummary summary;
  summary.particles = sim.particle_count();
  summary.threads = backend.threads();
  summary.openmp_wait = openmp_wait();
  summary.backend = Backend::kName;
  summary.precision = scene.precision;

  // A checkpoint belongs to the scene text the run wrote first: re-reading that text resolves the
  // same simulation, though not always to the same text.
  const std::string resolved_toml =
      options.resume ? read_text_file(options.out_dir + "/scene.resolved.toml") : loaded.resolved_toml;
  RunCheckpoint progress;  // where the run stands at its last output frame (or where it resumed)
  if (options.resume) {
    const std::string path = checkpoint_path(options.out_dir);
    progress = read_checkpoint(path, resolved_toml);
    StateReader in(progress.engine_state);
    try {
      stepper.load_state(in);
    } catch (const CheckpointError& e) {
      throw CheckpointError(path + ": " + e.what());
    }
    StateReader::expect(!options.rest_positions || sim.has(Attribute::x0),
                        path + ": the run kept no rest positions, which --render surface and --mesh need; "
                               "resume without them");
    summary.particle_steps = progress.particle_steps;
  } else {
    progress.metrics =
        "frame,step,time,dt,particles,kinetic_energy,elastic_energy,momentum_x,momentum_y,momentum_z,max_speed,min_J,"
        "plastic_work,gravity_work,collider_work,load_work,energy_residual" +
        scene_metrics->header() + "\n";
  }
  make_directories(options.out_dir);
  if (!options.resume) remove_particle_frames(options.out_dir + "/particles");  // an earlier run's
  if (scene.output.particles) make_directories(options.out_dir + "/particles");
  const std::string map_dir = scene_metrics->map_dir().empty() ? "" : options.out_dir + "/" + scene_metrics->map_dir();
  if (!map_dir.empty()) make_directories(map_dir);
  if (!options.resume) write_file_atomically(options.out_dir + "/scene.resolved.toml", resolved_toml);
  double step_seconds = progress.step_seconds;

  ParticleVtpWriter particle_frames;
  auto write_frame = [&](int frame) {
    const Diagnostics d = sim.diagnostics();
    if (frame == 0) progress.initial_energy = d.kinetic_energy + d.elastic_energy;
    const EnergyBudget& b = sim.energy_budget();
    const double residual = progress.initial_energy + b.gravity + b.colliders + b.loads - b.plastic -
                            d.kinetic_energy - d.elastic_energy;
    char row[768];
    std::snprintf(row, sizeof row,
                  "%d,%ld,%.9g,%.9g,%zu,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g", frame,
                  sim.steps(), sim.time(), sim.last_dt(), sim.particle_count(), d.kinetic_energy, d.elastic_energy,
                  d.momentum[0], d.momentum[1], d.momentum[2], d.max_speed, d.min_J, b.plastic, b.gravity, b.colliders,
                  b.loads, residual);
    progress.metrics += row + scene_metrics->row(sim, map_dir.empty() ? "" : map_dir + "/" + frame_name(frame)) + "\n";
    if (scene.output.particles) particle_frames.write(options.out_dir + "/particles/" + frame_name(frame) + ".vtp", sim);
    write_file_atomically(options.out_dir + "/metrics.csv", progress.metrics);
    if (options.on_frame) {
      const ParticleView<T> view = sim.particles();
      std::vector<Collider<double>> colliders;  // where they are now
      for (std::size_t c = 0; c < sim.collider_count(); ++c) colliders.push_back(sim.collider(int(c)).collider);
      options.on_frame(describe_frame(sim, materials, view, frame, colliders));
    }
  };
  // The checkpoint of the run as it stands, heading for output frame `next_frame`.
  auto capture = [&](int next_frame) {
    progress.next_frame = next_frame;
    progress.particle_steps = summary.particle_steps;
    progress.step_seconds = step_seconds;
    StateWriter out;
    stepper.save_state(out);
    progress.engine_state = out.bytes();
  };
  auto write_checkpoint_now = [&] { write_checkpoint(checkpoint_path(options.out_dir), resolved_toml, progress); };

  const int frames = std::max(1, int(std::ceil(scene.end_time / scene.frame_interval - 1e-9)));
  const double every = options.checkpoint_every;
  double next_checkpoint = every > 0 ? every * std::floor(sim.time() / every + 1 + 1e-9) : 0;
  bool captured_unwritten = false;  // progress holds a frame's state that is not on disk yet
  try {
    if (options.resume) write_file_atomically(options.out_dir + "/metrics.csv", progress.metrics);
    else write_frame(0);
    for (int f = progress.next_frame; f <= frames; ++f) {
      const double target = std::min(scene.end_time, f * scene.frame_interval);
      while (stepper.before(target)) {
        if (options.interrupt && options.interrupt->load()) {
          capture(f);
          write_checkpoint_now();
          captured_unwritten = false;
          throw std::runtime_error("interrupted");
        }
        const auto t0 = Clock::now();
        if (options.profile) sim.backend().profile = &profile;
        stepper.step_toward(target);
        sim.backend().profile = nullptr;
        step_seconds += seconds_since(t0);
        summary.particle_steps += double(sim.particle_count());
        if (options.progress) options.progress({sim.time(), scene.end_time, sim.steps(), f, frames, step_seconds});
      }
      write_frame(f);
      if (every > 0 && f < frames) {
        capture(f + 1);
        captured_unwritten = true;
        if (sim.time() >= next_checkpoint * (1 - 1e-12)) {
          write_checkpoint_now();
          captured_unwritten = false;
          while (next_checkpoint <= sim.time() * (1 + 1e-12)) next_checkpoint += every;
        }
      }
    }
  } catch (const StabilityError& e) {
    summary.status = "unstable";
    summary.error = e.what();
  } catch (const std::exception& e) {
    const bool interrupted = options.interrupt && options.interrupt->load();
    summary.status = interrupted ? "interrupted" : "failed";
    summary.error = interrupted ? "interrupted by a signal at t = " + std::to_string(sim.time()) + " s" : e.what();
  }
  // A guard stop or a failure leaves the last output frame's state as the checkpoint.
  if (captured_unwritten && summary.status != "ok") {
    try {
      write_checkpoint_now();
    } catch (const std::exception& e) {
      summary.error += "; the checkpoint could not be written: " + std::string(e.what());
    }
  }
  summary.steps = sim.steps();
  summary.simulated_time = sim.time();
  summary.step_seconds = step_seconds;
  char hash[20];
  std::snprintf(hash, sizeof hash, "%016" PRIx64, sim.state_hash());
  summary.state_hash = hash;
  summary.peak_memory_mb = peak_memory_mb();
  summary.launches = profile.entries;
  summary.wall_seconds = seconds_since(wall0);
  write_file_atomically(options.out_dir + "/summary.json", summary.to_json());
  return summary;
}

// Runs the scene in its precision on `backend`.
template <class Backend>
RunSummary run_on(const LoadedScene& scene, const RunOptions& options, const Backend& backend) {
  const backend::UseMemorySpace memory(Backend::memory());
  return scene.spec.precision == "double" ? run<double>(scene, options, backend) : run<float>(scene, options, backend);
}

}  // namespace scene_run_detail
}  // namespace firn
