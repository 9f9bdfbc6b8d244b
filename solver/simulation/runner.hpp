// Runs a simulation to its end time: advances the schedule, lands exactly on output and sample
// times, records observers, writes snapshots, reports progress through a callback (physics code
// never prints), and turns a divergence into a recorded outcome instead of a crash.
#pragma once

#include "observers/point_observer.hpp"
#include "simulation/simulation.hpp"
#include "time/schedule.hpp"

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

struct RunOptions {
  Real end_time = 0.0;
  Real observer_interval = 0.0;  // 0: every advection step
  Real snapshot_interval = 0.0;  // 0: no snapshots
  std::filesystem::path snapshot_dir;  // where VTP files go (required for snapshots)
  std::vector<Real> sample_times;      // extra exact times at which on_sample is called
  std::function<void(const Simulation&)> on_sample;
  std::function<void(const RunProgress&)> on_progress;
  double progress_interval_s = 1.0;
};

struct RunResult {
  bool completed = false;
  std::optional<DivergenceInfo> divergence;
  double wall_s = 0.0;
  double cpu_s = 0.0;
  Real end_time_reached = 0.0;
  StepCounters steps;
  std::vector<ObserverSeries> series;
};

RunResult run_simulation(Simulation& sim, Schedule& schedule, const std::vector<ObserverSpec>& observers,
                         const RunOptions& options);

// Writes one CSV per observer series (time first) into `dir`, atomically.
void write_observer_series(const std::vector<ObserverSeries>& series, const std::filesystem::path& dir);

}  // namespace mrsph
