#include "simulation/runner.hpp"

#include "io/csv_table.hpp"
#include "io/vtp_writer.hpp"
#include "observers/snapshot.hpp"
#include "simulation/checkpoint.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <map>
#include <stdexcept>

namespace mrsph {

namespace {

bool reached(Real t, Real target) { return t >= target - 1e-10 * std::max(Real(1), std::abs(target)); }

class SnapshotWriter {
 public:
  // `earlier` are the times of snapshots already written (a restarted run lists them again).
  SnapshotWriter(std::filesystem::path dir, const Simulation& sim, const std::vector<Real>& earlier) : dir_(std::move(dir)) {
    for (const Real t : earlier) {
      const int k = count_++;
      if (sim.has_fluid()) list(sim.fluid().name, k, t);
      for (const SolidBody& s : sim.solids()) list(s.name, k, t);
      if (k == 0)
        for (const WallBody& w : sim.walls()) list(w.name, k, t);
    }
  }
  void write(const Simulation& sim) {
    const int k = count_++;
    if (sim.has_fluid()) add(sim.fluid().name, k, sim.time, fluid_snapshot(sim));
    for (const SolidBody& s : sim.solids()) add(s.name, k, sim.time, solid_snapshot(s));
    if (k == 0)  // walls do not move: one file, listed in their collection once
      for (const WallBody& w : sim.walls()) add(w.name, k, sim.time, wall_snapshot(w));
    for (const auto& [body, entries] : collections_) write_pvd(dir_ / (body + ".pvd"), entries);
  }

 private:
  static std::string file_name(const std::string& body, int k) { return fmt::format("{}_{:05d}.vtp", body, k); }
  void list(const std::string& body, int k, Real t) { collections_[body].push_back(PvdEntry{t, "vtp/" + file_name(body, k)}); }
  void add(const std::string& body, int k, Real t, const PointCloud& cloud) {
    write_vtp(dir_ / "vtp" / file_name(body, k), cloud);
    list(body, k, t);
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
  RunnerState state;
  for (const ObserverSpec& spec : observer_specs) {
    observers.emplace_back(spec, sim);
    state.series.push_back(ObserverSeries{spec.name, observers.back().columns(), {}, {}});
    for (std::size_t k : observers.back().force_contacts()) sim.fluid_contacts()[k].records_impulse = true;
  }
  auto record = [&] {
    for (std::size_t k = 0; k < observers.size(); ++k) {
      state.series[k].time.push_back(sim.time);
      state.series[k].values.push_back(observers[k].sample(sim));
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

  const bool checkpoints = !options.checkpoint_path.empty();
  const bool keep_last_good = !options.last_good_path.empty();
  if ((checkpoints || keep_last_good) && !options.scene_document)
    throw std::invalid_argument("run_simulation: checkpoints need the scene document");
  auto serialise = [&] { return serialise_checkpoint(*options.scene_document, options.scene_file, sim, state); };
  auto checkpoint = [&] {
    write_checkpoint(options.checkpoint_path, serialise());
    result.checkpoint_written = options.checkpoint_path;
  };

  std::optional<SnapshotWriter> snapshots;
  if (options.resume) {
    state = *options.resume;
    while (next_sample < samples.size() && samples[next_sample] <= sim.time) ++next_sample;  // already taken
    if (options.snapshot_interval > 0.0) {
      // The checkpointed run may have written no snapshots (its next one then lies at t = 0) or
      // written them at another interval: the next one is due within one interval from now.
      if (reached(sim.time, state.next_snapshot) || state.next_snapshot > sim.time + options.snapshot_interval)
        state.next_snapshot = sim.time + options.snapshot_interval;
      snapshots.emplace(options.snapshot_dir, sim, state.snapshot_times);
    }
  } else {
    state.next_observation = sim.time + options.observer_interval;
    state.next_snapshot = sim.time + options.snapshot_interval;
    record();
    if (options.snapshot_interval > 0.0) {
      snapshots.emplace(options.snapshot_dir, sim, std::vector<Real>{});
      snapshots->write(sim);
      state.snapshot_times.push_back(sim.time);
    }
    handle_samples();
    update_compressibility_record(sim, state.compressibility);
  }
  Real next_checkpoint = sim.time + options.checkpoint_interval;
  double next_wall_checkpoint = options.checkpoint_wall_interval_s;
  double next_progress = options.progress_interval_s;
  std::string last_good;
  long long steps_since_last_good = 0;
  if (keep_last_good) last_good = serialise();

  try {
    while (!reached(sim.time, options.end_time)) {
      Real target = options.end_time;
      if (options.observer_interval > 0.0) target = std::min(target, state.next_observation);
      if (snapshots) target = std::min(target, state.next_snapshot);
      if (next_sample < samples.size()) target = std::min(target, samples[next_sample]);
      if (!(target > sim.time))
        throw std::logic_error(fmt::format("run_simulation: the next stop, t = {}, is not after the current time {}", target, sim.time));
      schedule.advance(sim, target - sim.time);
      update_compressibility_record(sim, state.compressibility);

      if (options.observer_interval <= 0.0) {
        record();
      } else if (reached(sim.time, state.next_observation)) {
        record();
        while (reached(sim.time, state.next_observation)) state.next_observation += options.observer_interval;
      }
      if (snapshots && reached(sim.time, state.next_snapshot)) {
        snapshots->write(sim);
        state.snapshot_times.push_back(sim.time);
        while (reached(sim.time, state.next_snapshot)) state.next_snapshot += options.snapshot_interval;
      }
      handle_samples();
      if (keep_last_good && ++steps_since_last_good >= options.last_good_interval) {
        last_good = serialise();
        steps_since_last_good = 0;
      }
      if (options.stop_requested && options.stop_requested->load()) {
        if (checkpoints) checkpoint();
        result.interrupted = true;
        break;
      }
      if (checkpoints && ((options.checkpoint_interval > 0.0 && reached(sim.time, next_checkpoint)) ||
                          (options.checkpoint_wall_interval_s > 0.0 && wall_seconds() >= next_wall_checkpoint))) {
        checkpoint();
        while (options.checkpoint_interval > 0.0 && reached(sim.time, next_checkpoint)) next_checkpoint += options.checkpoint_interval;
        next_wall_checkpoint = wall_seconds() + options.checkpoint_wall_interval_s;
      }
      if (options.on_progress && wall_seconds() >= next_progress) {
        options.on_progress(RunProgress{sim.time, options.end_time, sim.steps, wall_seconds()});
        next_progress = wall_seconds() + options.progress_interval_s;
      }
    }
    result.completed = !result.interrupted;
  } catch (const DivergenceError& e) {
    result.divergence = e.info();
    if (keep_last_good) {
      write_checkpoint(options.last_good_path, last_good);
      result.last_good_written = options.last_good_path;
    }
  }
  result.series = std::move(state.series);
  result.compressibility = state.compressibility;
  result.end_time_reached = sim.time;
  result.steps = sim.steps;
  result.wall_s = wall_seconds();
  result.cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return result;
}

const ObserverSeries& series_named(const std::vector<ObserverSeries>& series, const std::string& name) {
  for (const ObserverSeries& s : series)
    if (s.name == name) return s;
  throw std::runtime_error("no observer series '" + name + "'");
}

std::vector<Real> series_column(const ObserverSeries& series, std::size_t column) {
  std::vector<Real> out;
  for (const auto& row : series.values) out.push_back(row.at(column));
  return out;
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
