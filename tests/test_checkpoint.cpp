#include "checkpoint_fixture.hpp"
#include "core/thread_limit.hpp"
#include "run/checkpoint.hpp"
#include "scene/scene_loader.hpp"
#include "run/runner.hpp"

#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>

using namespace mrsph;

namespace {

const std::filesystem::path kScene = std::filesystem::path(MRSPH_SOURCE_DIR) / "verification/scenes/turek_hron_fsi2.json";
constexpr double kEnd = 0.8;

// Every state array of the simulation, as bytes, for bitwise comparison.
std::string state_bytes(const LoadedScene& s, const RunnerState& runner) {
  return serialise_checkpoint(s.document, s.file, *s.simulation, runner);
}

RunOptions options_for(const LoadedScene& s) {
  RunOptions o;
  o.end_time = kEnd;
  // Records every 0.2, so the checkpoint (after t = 0.4, at an advection step's end) falls inside an
  // interval over which the force observer averages: its impulse record must survive the restart.
  o.observer_interval = 0.2;
  o.scene_document = &s.document;
  o.scene_file = s.file;
  return o;
}

RunnerState runner_state(const RunResult& r) {
  RunnerState st;
  st.series = r.series;
  return st;
}

bool same_series(const std::vector<ObserverSeries>& a, const std::vector<ObserverSeries>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k].time != b[k].time || a[k].values.size() != b[k].values.size()) return false;
    for (std::size_t r = 0; r < a[k].values.size(); ++r)
      if (std::memcmp(a[k].values[r].data(), b[k].values[r].data(), a[k].values[r].size() * sizeof(double)) != 0) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("A run restarted from a checkpoint equals the uninterrupted run bitwise", "[checkpoint]") {
  const auto dir = std::filesystem::temp_directory_path() / "mrsph_test_checkpoint";
  std::filesystem::create_directories(dir);

  LoadedScene whole = load_scene(kScene, {});
  const RunResult uninterrupted = run_simulation(*whole.simulation, *whole.schedule, whole.observers, options_for(whole));
  REQUIRE(uninterrupted.completed);

  // Stop at the first advection-step boundary after t = 0.4 (no step is shortened).
  LoadedScene first = load_scene(kScene, {});
  const auto checkpoint = dir / "checkpoint.bin";
  const RunResult part = run_until_stopped(first, options_for(first), 0.4, checkpoint);
  REQUIRE(part.interrupted);
  REQUIRE_FALSE(part.completed);
  REQUIRE(std::filesystem::exists(checkpoint));

  // Restore into a freshly built scene and finish.
  Restored restored = restore_from(checkpoint);
  LoadedScene& second = restored.scene;
  CHECK(second.simulation->time == part.end_time_reached);
  RunOptions o2 = options_for(second);
  o2.resume = &restored.resume;
  const RunResult rest = run_simulation(*second.simulation, *second.schedule, second.observers, o2);
  REQUIRE(rest.completed);

  CHECK(rest.steps.advection == uninterrupted.steps.advection);
  CHECK(rest.steps.solid == uninterrupted.steps.solid);
  CHECK(same_series(rest.series, uninterrupted.series));
  // The compressibility record covers the whole run, the part before the checkpoint included.
  CHECK(rest.compressibility.density_deviation.value == uninterrupted.compressibility.density_deviation.value);
  CHECK(rest.compressibility.density_deviation.time == uninterrupted.compressibility.density_deviation.time);
  CHECK(rest.compressibility.mach.value == uninterrupted.compressibility.mach.value);
  CHECK(rest.compressibility.mach.time == uninterrupted.compressibility.mach.time);
  CHECK(state_bytes(second, runner_state(rest)) == state_bytes(whole, runner_state(uninterrupted)));
  std::filesystem::remove_all(dir);
}

TEST_CASE("A kept checkpoint written after its series have grown is the checkpoint of the moment it was kept",
          "[checkpoint]") {
  LoadedScene s = load_scene(kScene, {});
  const RunResult r = run_simulation(*s.simulation, *s.schedule, s.observers, options_for(s));
  REQUIRE(r.completed);
  // The runner keeps the last good state this way every few steps, and writes it only on divergence.
  RunnerState then = runner_state(r);
  for (ObserverSeries& series : then.series) {
    REQUIRE(series.time.size() >= 3);
    series.time.resize(2);
    series.values.resize(2);
  }
  KeptCheckpoint kept;
  keep_checkpoint(s.document, s.file, *s.simulation, then, kept);
  CHECK(assemble_checkpoint(kept, r.series) == state_bytes(s, then));
  // Kept again into the same buffers: the later moment, whole series.
  keep_checkpoint(s.document, s.file, *s.simulation, runner_state(r), kept);
  CHECK(assemble_checkpoint(kept, r.series) == state_bytes(s, runner_state(r)));
  // Series shorter than those kept are not the ones it was kept from.
  CHECK_THROWS_AS(assemble_checkpoint(kept, then.series), std::logic_error);
}

TEST_CASE("A checkpoint from another scene is refused with a clear message", "[checkpoint]") {
  const auto dir = std::filesystem::temp_directory_path() / "mrsph_test_checkpoint_mismatch";
  std::filesystem::create_directories(dir);
  LoadedScene s = load_scene(kScene, {});
  RunnerState st;
  write_checkpoint(dir / "c.bin", serialise_checkpoint(s.document, s.file, *s.simulation, st));
  LoadedScene other = load_scene(kScene, {"parameters.ratio=1"});
  RunnerState resume;
  CHECK_THROWS_WITH(restore_checkpoint(dir / "c.bin", *other.simulation, resume),
                    Catch::Contains("from another scene") || Catch::Contains("differ") || Catch::Contains("observer"));
  std::ofstream(dir / "junk.bin") << "not a checkpoint";
  CHECK_THROWS_WITH(read_checkpoint_header(dir / "junk.bin"), Catch::Contains("not an mrsph checkpoint"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("The same scene gives bitwise identical results, run to run and for 1 or 2 threads", "[determinism]") {
  std::string reference;
  std::vector<ObserverSeries> reference_series;
  for (int threads : {2, 2, 1}) {
    run_with_threads(threads, [&] {
    LoadedScene s = load_scene(kScene, {});
    RunOptions o = options_for(s);
    o.end_time = 0.5;
    const RunResult r = run_simulation(*s.simulation, *s.schedule, s.observers, o);
    REQUIRE(r.completed);
    const std::string bytes = state_bytes(s, runner_state(r));
    if (reference.empty()) {
      reference = bytes;
      reference_series = r.series;
    } else {
      CHECK(bytes == reference);
      CHECK(same_series(r.series, reference_series));
    }
    return 0;
    });
  }
}

TEST_CASE("A restart may ask for snapshots the checkpointed run did not write", "[checkpoint]") {
  // The checkpoint's next snapshot time is then t = 0, behind the restart time; the run once
  // advanced by that negative interval and diverged at once.
  const auto dir = std::filesystem::temp_directory_path() / "mrsph_test_checkpoint_snapshots";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  LoadedScene first = load_scene(kScene, {});
  RunOptions o1 = options_for(first);
  o1.end_time = 0.2;
  o1.checkpoint_path = dir / "checkpoint.bin";
  o1.checkpoint_interval = 0.1;
  const RunResult part = run_simulation(*first.simulation, *first.schedule, first.observers, o1);
  REQUIRE(part.completed);

  Restored restored = restore_from(o1.checkpoint_path);
  LoadedScene& second = restored.scene;
  const Real restart_time = second.simulation->time;
  REQUIRE(restart_time > 0.1);
  RunOptions o2 = options_for(second);
  o2.end_time = restart_time + 0.05;
  o2.snapshot_interval = 0.02;
  o2.snapshot_dir = dir / "snapshots";
  o2.resume = &restored.resume;
  const RunResult rest = run_simulation(*second.simulation, *second.schedule, second.observers, o2);
  REQUIRE(rest.completed);
  CHECK_FALSE(rest.divergence);
  CHECK(rest.end_time_reached == Approx(o2.end_time));
  // Snapshots at restart + 0.02 and + 0.04 (the first one an interval after the restart).
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "snapshots" / "vtp"))
    if (entry.path().filename().string().rfind("beam_", 0) == 0) ++files;
  CHECK(files == 2);
  std::filesystem::remove_all(dir);
}
