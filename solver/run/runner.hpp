// Runs a simulation to its end time: advances the schedule, records observers, writes snapshots
// and calls back for samples after the first advection step at or past each of their times (they
// never shorten a step, so how often a run is watched does not change its results; only the last
// step is cut, to end on the end time), reports progress through a callback (physics code never
// prints), and turns a divergence into a recorded outcome instead of a crash.
#pragma once

#include "observers/compressibility_monitor.hpp"
#include "observers/point_observer.hpp"
#include "simulation/simulation.hpp"
#include "time/schedule.hpp"

#include "scene/scene_node.hpp"

#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mrsph {

struct RunProgress {
  Real time;
  Real end_time;
  StepCounters steps;
  double wall_s;
};

struct ObserverSeries {
  std::string name;
  std::vector<std::string> columns;  // without the time column
  std::vector<Real> time;
  std::vector<std::vector<Real>> values;
};

// The series of the observer called `name` (throws std::runtime_error naming it if absent).
const ObserverSeries& series_named(const std::vector<ObserverSeries>& series, const std::string& name);
// One value column of a series (0: the first after time).
std::vector<Real> series_column(const ObserverSeries& series, std::size_t column);

// The runner's own state, saved in checkpoints so outputs continue seamlessly after a restart.
struct RunnerState {
  Real next_observation = 0.0;
  Real next_snapshot = 0.0;
  std::vector<Real> snapshot_times;
  std::vector<ObserverSeries> series;
  CompressibilityRecord compressibility;
};

struct RunOptions {
  Real end_time = 0.0;
  Real observer_interval = 0.0;  // 0: every advection step
  Real snapshot_interval = 0.0;  // 0: no snapshots
  std::filesystem::path snapshot_dir;  // where VTP files go (required for snapshots)
  std::vector<Real> sample_times;      // on_sample is called after the first step at or past each
                                       // (once per time, with the simulation's own time)
  std::function<void(const Simulation&)> on_sample;
  std::function<void(const RunProgress&)> on_progress;
  double progress_interval_s = 1.0;

  // Checkpoints (checkpoint.hpp), written to checkpoint_path at the end of the first advection step
  // after each checkpoint_interval of simulated time and each checkpoint_wall_interval_s of wall
  // time (0: never), and when *stop_requested becomes true (the run then stops: interrupted).
  // Checkpoints, like outputs, never shorten a step, so they do not change the results.
  std::filesystem::path checkpoint_path;
  Real checkpoint_interval = 0.0;
  double checkpoint_wall_interval_s = 0.0;
  const std::atomic<bool>* stop_requested = nullptr;
  // The last good state, kept in memory every last_good_interval advection steps and written to
  // last_good_path if the run diverges (empty: not kept).
  std::filesystem::path last_good_path;
  int last_good_interval = 10;
  // The scene stored in checkpoints (required for checkpoints and the last good state).
  const Json* scene_document = nullptr;
  std::string scene_file;
  // Continue a run restored from a checkpoint (restore_checkpoint filled the simulation and this).
  const RunnerState* resume = nullptr;
};

struct RunResult {
  bool completed = false;
  bool interrupted = false;  // stopped on request, with a checkpoint written
  std::optional<DivergenceInfo> divergence;
  std::filesystem::path checkpoint_written;  // the latest checkpoint, if any
  std::filesystem::path last_good_written;   // written when the run diverged, if kept
  double wall_s = 0.0;
  double cpu_s = 0.0;
  Real end_time_reached = 0.0;
  StepCounters steps;
  std::vector<ObserverSeries> series;
  CompressibilityRecord compressibility;  // over the whole run, a restarted one included
};

RunResult run_simulation(Simulation& sim, Schedule& schedule, const std::vector<ObserverSpec>& observers,
                         const RunOptions& options);

// Writes one CSV per observer series (time first) into `dir`, atomically.
void write_observer_series(const std::vector<ObserverSeries>& series, const std::filesystem::path& dir);

}  // namespace mrsph
