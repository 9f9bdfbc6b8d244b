#include "run/checkpoint.hpp"

#include "io/atomic_file.hpp"
#include "io/binary_stream.hpp"

#include <fstream>
#include <stdexcept>
#include <sstream>
#include <utility>

namespace mrsph {

namespace {

constexpr char kMagic[8] = {'M', 'R', 'S', 'P', 'H', 'C', 'K', '1'};
constexpr std::uint32_t kVersion = 5;  // 2: the compressibility record; 3: open boundaries (particle count, zones, ledgers);
                                       // 4: the solids' contact stiffnesses; 5: the force observers' impulse records

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open checkpoint " + path.string());
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

BinaryReader open_reader(const std::filesystem::path& path) {
  BinaryReader r(read_all(path), path.string());
  for (char c : kMagic)
    if (r.value<char>() != c) throw std::runtime_error(path.string() + " is not an mrsph checkpoint");
  const auto version = r.value<std::uint32_t>();
  if (version != kVersion)
    throw std::runtime_error(path.string() + ": checkpoint version " + std::to_string(version) + ", this program reads " +
                             std::to_string(kVersion));
  return r;
}

// The same order in both directions: one function per body kind, parameterised by the visitor.
struct Saver {
  BinaryWriter& w;
  template <class T>
  void operator()(const std::vector<T>& a, const char*) { w.array(a); }
};
struct Loader {
  BinaryReader& r;
  template <class T>
  void operator()(std::vector<T>& a, const char* what) { a = r.array<T>(a.size(), what); }
};

// The force observers' impulse record (FluidContact::recorded_*): a restart inside an observer
// interval continues its average.
void save_impulse_record(BinaryWriter& w, const FluidContact& c) {
  for (Real v : {c.recorded_impulse.x(), c.recorded_impulse.y(), c.recorded_viscous_impulse.x(),
                 c.recorded_viscous_impulse.y(), c.recorded_duration})
    w.value(v);
}

void load_impulse_record(BinaryReader& r, FluidContact& c) {
  for (Vec2* v : {&c.recorded_impulse, &c.recorded_viscous_impulse}) {
    v->x() = r.value<Real>();
    v->y() = r.value<Real>();
  }
  c.recorded_duration = r.value<Real>();
}

}  // namespace

namespace {

// Everything before the observers' series: the scene, the clock and the runner's output state.
void write_scene_clock_and_runner(BinaryWriter& w, const Json& scene_document, const std::string& scene_file,
                                  const Simulation& sim, const RunnerState& runner) {
  for (char c : kMagic) w.value(c);
  w.value(kVersion);
  w.text(scene_document.dump());
  w.text(scene_file);
  w.value(sim.time);
  w.value(sim.steps.advection);
  w.value(sim.steps.acoustic);
  w.value(sim.steps.solid);
  w.value<std::uint64_t>(sim.rebuild_count());
  w.value(runner.next_observation);
  w.value(runner.next_snapshot);
  w.array(runner.snapshot_times);
  for (const FluidExtreme* e : {&runner.compressibility.density_deviation, &runner.compressibility.mach}) {
    w.value(e->value);
    w.value(e->time);
    w.value(e->position);
  }
}

// The observers' series, each cut to its first rows[k] rows.
void write_series(BinaryWriter& w, const std::vector<ObserverSeries>& series, const std::vector<std::size_t>& rows) {
  w.value<std::uint64_t>(series.size());
  for (std::size_t k = 0; k < series.size(); ++k) {
    const ObserverSeries& s = series[k];
    w.text(s.name);
    w.array(s.time.data(), rows[k]);
    std::vector<Real> flat;
    for (std::size_t row = 0; row < rows[k]; ++row) flat.insert(flat.end(), s.values[row].begin(), s.values[row].end());
    w.value<std::uint64_t>(s.columns.size());
    w.array(flat);
  }
}

// Every particle array the next steps read, and the boundaries' and contacts' records.
void write_particle_state(BinaryWriter& w, const Simulation& sim) {
  Saver save{w};
  w.value<std::uint8_t>(sim.has_fluid());
  if (sim.has_fluid()) {
    // Open boundaries create and delete particles: the count is part of the state.
    w.value<std::uint64_t>(sim.fluid().particles.size());
    FluidParticles::for_each_field(sim.fluid().particles, save);
  }
  w.value<std::uint64_t>(sim.open_boundaries.size());
  for (const OpenBoundary& b : sim.open_boundaries) {
    w.value(b.ledger.mass_into_domain);
    w.value(b.ledger.created);
    w.value(b.ledger.deleted);
    w.array(b.mean_normal_velocity);
  }
  w.value<std::uint64_t>(sim.fluid_contacts().size());
  for (const FluidContact& c : sim.fluid_contacts()) {
    save(c.boundary_dissipation_reaction, "");
    save_impulse_record(w, c);
  }
  w.value<std::uint64_t>(sim.solids().size());
  for (const SolidBody& solid : sim.solids()) SolidParticles::for_each_state_field(solid.particles, save);
}

}  // namespace

void keep_checkpoint(const Json& scene_document, const std::string& scene_file, const Simulation& sim,
                     const RunnerState& runner, KeptCheckpoint& kept) {
  BinaryWriter before(std::move(kept.before_series));
  write_scene_clock_and_runner(before, scene_document, scene_file, sim, runner);
  kept.before_series = std::move(before).take();
  kept.series_rows.clear();
  for (const ObserverSeries& s : runner.series) kept.series_rows.push_back(s.time.size());
  BinaryWriter after(std::move(kept.after_series));
  write_particle_state(after, sim);
  kept.after_series = std::move(after).take();
}

std::string assemble_checkpoint(const KeptCheckpoint& kept, const std::vector<ObserverSeries>& series) {
  bool grown = kept.series_rows.size() == series.size();
  for (std::size_t k = 0; grown && k < series.size(); ++k)
    grown = kept.series_rows[k] <= series[k].time.size() && kept.series_rows[k] <= series[k].values.size();
  if (!grown) throw std::logic_error("assemble_checkpoint: the observer series are not those kept, grown");
  BinaryWriter w;
  w.raw(kept.before_series);
  write_series(w, series, kept.series_rows);
  w.raw(kept.after_series);
  return std::move(w).take();
}

std::string serialise_checkpoint(const Json& scene_document, const std::string& scene_file, const Simulation& sim,
                                 const RunnerState& runner) {
  KeptCheckpoint kept;
  keep_checkpoint(scene_document, scene_file, sim, runner, kept);
  return assemble_checkpoint(kept, runner.series);
}

void write_checkpoint(const std::filesystem::path& path, const std::string& bytes) { write_file_atomically(path, bytes); }

CheckpointHeader read_checkpoint_header(const std::filesystem::path& path) {
  BinaryReader r = open_reader(path);
  CheckpointHeader h;
  try {
    h.scene_document = Json::parse(r.text());
  } catch (const Json::parse_error& e) {
    throw std::runtime_error(path.string() + ": the stored scene is not valid JSON: " + e.what());
  }
  h.scene_file = r.text();
  h.time = r.value<Real>();
  return h;
}

void restore_checkpoint(const std::filesystem::path& path, Simulation& sim, RunnerState& runner) {
  BinaryReader r = open_reader(path);
  r.text();  // scene document
  r.text();  // scene file
  sim.time = r.value<Real>();
  sim.steps.advection = r.value<long long>();
  sim.steps.acoustic = r.value<long long>();
  sim.steps.solid = r.value<long long>();
  const auto rebuilds = r.value<std::uint64_t>();
  runner.next_observation = r.value<Real>();
  runner.next_snapshot = r.value<Real>();
  runner.snapshot_times = r.array<Real>(BinaryReader::kAnySize, "snapshot times");
  for (FluidExtreme* e : {&runner.compressibility.density_deviation, &runner.compressibility.mach}) {
    e->value = r.value<Real>();
    e->time = r.value<Real>();
    e->position = r.value<Vec2>();
  }
  const auto series_count = r.value<std::uint64_t>();
  if (series_count != runner.series.size())
    throw std::runtime_error(path.string() + ": " + std::to_string(series_count) + " observer series, the scene has " +
                             std::to_string(runner.series.size()));
  for (ObserverSeries& s : runner.series) {
    const std::string name = r.text();
    if (name != s.name) throw std::runtime_error(path.string() + ": observer '" + name + "' where the scene has '" + s.name + "'");
    s.time = r.array<Real>(BinaryReader::kAnySize, "observer times");
    const auto columns = r.value<std::uint64_t>();
    if (columns != s.columns.size()) throw std::runtime_error(path.string() + ": observer '" + name + "' has other columns");
    const std::vector<Real> flat = r.array<Real>(s.time.size() * columns, "observer values");
    s.values.assign(s.time.size(), std::vector<Real>(columns));
    for (std::size_t k = 0; k < s.time.size(); ++k)
      for (std::size_t c = 0; c < columns; ++c) s.values[k][c] = flat[k * columns + c];
  }
  Loader load{r};
  const bool has_fluid = r.value<std::uint8_t>() != 0;
  if (has_fluid != sim.has_fluid()) throw std::runtime_error(path.string() + ": fluid body mismatch with the scene");
  if (has_fluid) {
    sim.fluid().particles.resize(r.value<std::uint64_t>());
    FluidParticles::for_each_field(sim.fluid().particles, load);
  }
  const auto open_boundaries = r.value<std::uint64_t>();
  if (open_boundaries != sim.open_boundaries.size())
    throw std::runtime_error(path.string() + ": open boundaries differ from the scene");
  for (OpenBoundary& b : sim.open_boundaries) {
    b.ledger.mass_into_domain = r.value<Real>();
    b.ledger.created = r.value<long long>();
    b.ledger.deleted = r.value<long long>();
    b.mean_normal_velocity = r.array<Real>(BinaryReader::kAnySize, "open boundary mean velocities");
  }
  const auto contacts = r.value<std::uint64_t>();
  if (contacts != sim.fluid_contacts().size()) throw std::runtime_error(path.string() + ": boundary bodies differ from the scene");
  for (FluidContact& c : sim.fluid_contacts()) {
    load(c.boundary_dissipation_reaction, "boundary dissipation reactions");
    load_impulse_record(r, c);
  }
  const auto solids = r.value<std::uint64_t>();
  if (solids != sim.solids().size()) throw std::runtime_error(path.string() + ": solid bodies differ from the scene");
  for (SolidBody& solid : sim.solids()) SolidParticles::for_each_state_field(solid.particles, load);
  if (!r.at_end()) throw std::runtime_error(path.string() + ": unexpected data after the last body");
  sim.restore_relations(rebuilds);
}

}  // namespace mrsph
