#include "simulation/runner.hpp"

#include "io/csv_table.hpp"
#include "io/vtp_writer.hpp"
#include "observers/snapshot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <map>

namespace mrsph {

namespace {

bool reached(Real t, Real target) { return t >= target - 1e-10 * std::max(Real(1), std::abs(target)); }

class SnapshotWriter {
 public:
  explicit SnapshotWriter(std::filesystem::path dir) : dir_(std::move(dir)) {}
  void write(const Simulation& sim) {
    const int k = count_++;
    if (sim.has_fluid()) add(sim.fluid().name, k, sim.time, fluid_snapshot(sim));
    for (const SolidBody& s : sim.solids()) add(s.name, k, sim.time, solid_snapshot(s));
    if (k == 0)  // walls do not move: one file, listed in their collection once
      for (const WallBody& w : sim.walls()) add(w.name, k, sim.time, wall_snapshot(w));
    for (const auto& [body, entries] : collections_) write_pvd(dir_ / (body + ".pvd"), entries);
  }

 private:
  void add(const std::string& body, int k, Real t, const PointCloud& cloud) {
    const std::string file = fmt::format("{}_{:05d}.vtp", body, k);
    write_vtp(dir_ / "vtp" / file, cloud);
    collections_[body].push_back(PvdEntry{t, "vtp/" + file});
  }
  std::filesystem::path dir_;
  int count_ = 0;
  std::map<std::string, std::vector<PvdEntry>> collections_;
};

}  // namespace

RunResult run_simulation(Simulation& sim, Schedule& schedule, const std::vector<ObserverSpec>& observer_specs,
                         const RunOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto wall_start = Clock::now();
  const std::clock_t cpu_start = std::clock();
  auto wall_seconds = [&] { return std::chrono::duration<double>(Clock::now() - wall_start).count(); };

  std::vector<PointObserver> observers;
  RunResult result;
  for (const ObserverSpec& spec : observer_specs) {
    observers.emplace_back(spec, sim);
    result.series.push_back(ObserverSeries{spec.name, observers.back().columns(), {}, {}});
  }
  auto record = [&] {
    for (std::size_t k = 0; k < observers.size(); ++k) {
      result.series[k].time.push_back(sim.time);
      result.series[k].values.push_back(observers[k].sample(sim));
    }
  };

  std::vector<Real> samples = options.sample_times;
  std::sort(samples.begin(), samples.end());
  std::size_t next_sample = 0;
  auto handle_samples = [&] {
    while (next_sample < samples.size() && reached(sim.time, samples[next_sample])) {
      if (options.on_sample) options.on_sample(sim);
      ++next_sample;
    }
  };

  std::optional<SnapshotWriter> snapshots;
  if (options.snapshot_interval > 0.0) snapshots.emplace(options.snapshot_dir);
  Real next_observation = sim.time + options.observer_interval;
  Real next_snapshot = sim.time + options.snapshot_interval;
  double next_progress = options.progress_interval_s;

  record();
  if (snapshots) snapshots->write(sim);
  handle_samples();

  try {
    while (!reached(sim.time, options.end_time)) {
      Real target = options.end_time;
      if (options.observer_interval > 0.0) target = std::min(target, next_observation);
      if (snapshots) target = std::min(target, next_snapshot);
      if (next_sample < samples.size()) target = std::min(target, samples[next_sample]);
      schedule.advance(sim, target - sim.time);

      if (options.observer_interval <= 0.0) {
        record();
      } else if (reached(sim.time, next_observation)) {
        record();
        while (reached(sim.time, next_observation)) next_observation += options.observer_interval;
      }
      if (snapshots && reached(sim.time, next_snapshot)) {
        snapshots->write(sim);
        while (reached(sim.time, next_snapshot)) next_snapshot += options.snapshot_interval;
      }
      handle_samples();
      if (options.on_progress && wall_seconds() >= next_progress) {
        options.on_progress(RunProgress{sim.time, options.end_time, sim.steps, wall_seconds()});
        next_progress = wall_seconds() + options.progress_interval_s;
      }
    }
    result.completed = true;
  } catch (const DivergenceError& e) {
    result.divergence = e.info();
  }
  result.end_time_reached = sim.time;
  result.steps = sim.steps;
  result.wall_s = wall_seconds();
  result.cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return result;
}

void write_observer_series(const std::vector<ObserverSeries>& series, const std::filesystem::path& dir) {
  for (const ObserverSeries& s : series) {
    CsvTable table;
    table.columns.push_back("time");
    for (const auto& c : s.columns) table.columns.push_back(c);
    for (std::size_t k = 0; k < s.time.size(); ++k) {
      std::vector<double> row{s.time[k]};
      row.insert(row.end(), s.values[k].begin(), s.values[k].end());
      table.add_row(std::move(row));
    }
    table.write(dir / (s.name + ".csv"));
  }
}

}  // namespace mrsph
