#include "run/runner.hpp"

#include "fsi/fluid_solid_coupling.hpp"
#include "io/csv_table.hpp"
#include "io/vtp_writer.hpp"
#include "observers/snapshot.hpp"
#include "run/checkpoint.hpp"

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

// One run of run_simulation, as named steps: set-up (observers, samples, checkpoints), the start
// (fresh or resumed), the loop's stop time and what follows each advection step, the result.
class RunLoop {
 public:
  RunLoop(Simulation& sim, const std::vector<ObserverSpec>& observer_specs, const RunOptions& options)
      : sim_(sim), options_(options), samples_(options.sample_times) {
    for (const ObserverSpec& spec : observer_specs) {
      observers_.emplace_back(spec, sim);
      state_.series.push_back(ObserverSeries{spec.name, observers_.back().columns(), {}, {}});
      for (std::size_t k : observers_.back().force_contacts()) sim.fluid_contacts()[k].records_impulse = true;
    }
    std::sort(samples_.begin(), samples_.end());
    if ((checkpoints() || keeps_last_good()) && !options.scene_document)
      throw std::invalid_argument("run_simulation: checkpoints need the scene document");
  }

  void start() {
    if (options_.resume) resume();
    else start_fresh();
    next_checkpoint_ = sim_.time + options_.checkpoint_interval;
    next_wall_checkpoint_ = options_.checkpoint_wall_interval_s;
    next_progress_ = options_.progress_interval_s;
    if (keeps_last_good()) keep_last_good();
  }

  bool finished() const { return reached(sim_.time, options_.end_time); }

  // The longest the next advection step may be: the time left to the end. Output, sample and
  // checkpoint times never shorten a step (each is taken after the first step that reaches it), so
  // how often a run is watched does not change its results.
  Real longest_step() const {
    if (!(options_.end_time > sim_.time))
      throw std::logic_error(fmt::format("run_simulation: the end time, t = {}, is not after the current time {}", options_.end_time, sim_.time));
    return options_.end_time - sim_.time;
  }

  // Records, snapshots, samples and the last good state after a step; false when a stop was
  // requested (a checkpoint is then written, if any are kept).
  bool after_step() {
    update_compressibility_record(sim_, state_.compressibility);
    if (options_.observer_interval <= 0.0) {
      record();
    } else if (reached(sim_.time, state_.next_observation)) {
      record();
      while (reached(sim_.time, state_.next_observation)) state_.next_observation += options_.observer_interval;
    }
    if (snapshots_ && reached(sim_.time, state_.next_snapshot)) {
      write_snapshot();
      while (reached(sim_.time, state_.next_snapshot)) state_.next_snapshot += options_.snapshot_interval;
    }
    handle_samples();
    if (keeps_last_good() && ++steps_since_last_good_ >= options_.last_good_interval) {
      keep_last_good();
      steps_since_last_good_ = 0;
    }
    if (options_.stop_requested && options_.stop_requested->load()) {
      if (checkpoints()) checkpoint();
      result_.interrupted = true;
      return false;
    }
    checkpoint_if_due();
    report_progress();
    return true;
  }

  void diverged(const DivergenceError& e) {
    result_.divergence = e.info();
    if (!keeps_last_good()) return;
    write_checkpoint(options_.last_good_path, assemble_checkpoint(last_good_, state_.series));
    result_.last_good_written = options_.last_good_path;
  }

  RunResult finish(bool completed) {
    result_.completed = completed && !result_.interrupted;
    result_.series = std::move(state_.series);
    result_.compressibility = state_.compressibility;
    result_.end_time_reached = sim_.time;
    result_.steps = sim_.steps;
    result_.wall_s = wall_seconds();
    result_.cpu_s = static_cast<double>(std::clock() - cpu_start_) / CLOCKS_PER_SEC;
    return std::move(result_);
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool checkpoints() const { return !options_.checkpoint_path.empty(); }
  bool keeps_last_good() const { return !options_.last_good_path.empty(); }
  double wall_seconds() const { return std::chrono::duration<double>(Clock::now() - wall_start_).count(); }
  std::string serialise() const { return serialise_checkpoint(*options_.scene_document, options_.scene_file, sim_, state_); }
  void keep_last_good() { keep_checkpoint(*options_.scene_document, options_.scene_file, sim_, state_, last_good_); }

  void record() {
    for (std::size_t k = 0; k < observers_.size(); ++k) {
      state_.series[k].time.push_back(sim_.time);
      state_.series[k].values.push_back(observers_[k].sample(sim_));
    }
    // Force observers average over the time since the previous record, so a record does not sample
    // one phase of an oscillation that the output times lock onto.
    clear_boundary_impulses(sim_.fluid_contacts());
  }
  void handle_samples() {
    while (next_sample_ < samples_.size() && reached(sim_.time, samples_[next_sample_])) {
      if (options_.on_sample) options_.on_sample(sim_);
      ++next_sample_;
    }
  }
  void write_snapshot() {
    snapshots_->write(sim_);
    state_.snapshot_times.push_back(sim_.time);
  }
  void checkpoint() {
    write_checkpoint(options_.checkpoint_path, serialise());
    result_.checkpoint_written = options_.checkpoint_path;
  }
  void checkpoint_if_due() {
    if (!checkpoints()) return;
    const bool by_time = options_.checkpoint_interval > 0.0 && reached(sim_.time, next_checkpoint_);
    const bool by_wall = options_.checkpoint_wall_interval_s > 0.0 && wall_seconds() >= next_wall_checkpoint_;
    if (!by_time && !by_wall) return;
    checkpoint();
    while (options_.checkpoint_interval > 0.0 && reached(sim_.time, next_checkpoint_)) next_checkpoint_ += options_.checkpoint_interval;
    next_wall_checkpoint_ = wall_seconds() + options_.checkpoint_wall_interval_s;
  }
  void report_progress() {
    if (!options_.on_progress || wall_seconds() < next_progress_) return;
    options_.on_progress(RunProgress{sim_.time, options_.end_time, sim_.steps, wall_seconds()});
    next_progress_ = wall_seconds() + options_.progress_interval_s;
  }

  void resume() {
    state_ = *options_.resume;
    while (next_sample_ < samples_.size() && samples_[next_sample_] <= sim_.time) ++next_sample_;  // already taken
    if (options_.snapshot_interval <= 0.0) return;
    // The checkpointed run may have written no snapshots (its next one then lies at t = 0) or
    // written them at another interval: the next one is due within one interval from now.
    if (reached(sim_.time, state_.next_snapshot) || state_.next_snapshot > sim_.time + options_.snapshot_interval)
      state_.next_snapshot = sim_.time + options_.snapshot_interval;
    snapshots_.emplace(options_.snapshot_dir, sim_, state_.snapshot_times);
  }
  void start_fresh() {
    state_.next_observation = sim_.time + options_.observer_interval;
    state_.next_snapshot = sim_.time + options_.snapshot_interval;
    record();
    if (options_.snapshot_interval > 0.0) {
      snapshots_.emplace(options_.snapshot_dir, sim_, std::vector<Real>{});
      write_snapshot();
    }
    handle_samples();
    update_compressibility_record(sim_, state_.compressibility);
  }

  Simulation& sim_;
  const RunOptions& options_;
  const Clock::time_point wall_start_ = Clock::now();
  const std::clock_t cpu_start_ = std::clock();
  std::vector<PointObserver> observers_;
  RunnerState state_;
  RunResult result_;
  std::vector<Real> samples_;
  std::size_t next_sample_ = 0;
  std::optional<SnapshotWriter> snapshots_;
  Real next_checkpoint_ = 0.0;
  double next_wall_checkpoint_ = 0.0, next_progress_ = 0.0;
  KeptCheckpoint last_good_;  // the series as they are when it is written, cut to its rows
  long long steps_since_last_good_ = 0;
};

}  // namespace

RunResult run_simulation(Simulation& sim, Schedule& schedule, const std::vector<ObserverSpec>& observer_specs,
                         const RunOptions& options) {
  RunLoop run(sim, observer_specs, options);
  run.start();
  try {
    while (!run.finished()) {
      schedule.advance(sim, run.longest_step());
      if (!run.after_step()) break;
    }
    return run.finish(true);
  } catch (const DivergenceError& e) {
    run.diverged(e);
  }
  return run.finish(false);
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
