// Interrupting a run with a checkpoint and restoring it, as `mrsph run` (SIGINT) and `mrsph restart` do.
#pragma once

#include "scene/scene_loader.hpp"
#include "run/checkpoint.hpp"
#include "run/runner.hpp"

#include <atomic>
#include <filesystem>

// Runs the scene with `options`, asking it to stop at the first advection-step boundary after
// `stop_time` (no step is shortened); the checkpoint goes to `checkpoint`.
inline mrsph::RunResult run_until_stopped(mrsph::LoadedScene& s, mrsph::RunOptions options, double stop_time,
                                          const std::filesystem::path& checkpoint) {
  std::atomic<bool> stop{false};
  options.checkpoint_path = checkpoint;
  options.stop_requested = &stop;
  options.progress_interval_s = 0.0;
  options.on_progress = [&](const mrsph::RunProgress& p) { if (p.time >= stop_time) stop = true; };
  return mrsph::run_simulation(*s.simulation, *s.schedule, s.observers, options);
}

// A scene rebuilt from a checkpoint and restored, with the runner state to resume.
struct Restored {
  mrsph::LoadedScene scene;
  mrsph::RunnerState resume;
};

inline Restored restore_from(const std::filesystem::path& checkpoint) {
  const mrsph::CheckpointHeader header = mrsph::read_checkpoint_header(checkpoint);
  Restored r{mrsph::build_scene(header.scene_document, header.scene_file), {}};
  for (const auto& spec : r.scene.observers)
    r.resume.series.push_back(mrsph::ObserverSeries{spec.name, mrsph::PointObserver(spec, *r.scene.simulation).columns(), {}, {}});
  mrsph::restore_checkpoint(checkpoint, *r.scene.simulation, r.resume);
  return r;
}
