#include "checkpoint_fixture.hpp"
#include "io/vtp_writer.hpp"
#include "observers/snapshot.hpp"
#include "scene_fixture.hpp"
#include "run/runner.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>

using namespace mrsph;

namespace {
const char* kChannel = R"({
    "parameters": {"dp": 0.05},
    "domain": {"lower": [0, -0.3], "upper": [1, 1.3], "periodic": [true, false]},
    "fluid": {"dp": "dp", "region": {"rectangle": {"lower": [0, 0], "upper": [1, 1]}}, "density": 1, "sound_speed": 10,
              "viscosity": 0.01, "initial_velocity": {"type": "uniform", "value": [1, 0]}},
    "walls": [{"name": "bottom", "dp": "dp", "region": {"rectangle": {"lower": [0, "-4*dp"], "upper": [1, 0]}}},
              {"name": "top", "dp": "dp", "region": {"rectangle": {"lower": [0, 1], "upper": [1, "1+4*dp"]}}}],
    "end_time": 0.5})";
}

TEST_CASE("A diverging run is stopped and reported with time, step, body and particle", "[run]") {
  // An acoustic step five times the CFL limit (paper Eq. 33 uses 0.6) is unstable.
  Json doc = Json::parse(kChannel);
  doc["fluid"]["acoustic_cfl"] = 5.0;
  doc["fluid"]["advection_cfl"] = 5.0;
  LoadedScene s = build_scene(doc, "unstable.json");
  const auto dir = std::filesystem::temp_directory_path() / "mrsph_test_diverging_run";
  std::filesystem::create_directories(dir);
  RunOptions options;
  options.end_time = 0.5;
  options.last_good_path = dir / "last_good.bin";
  options.scene_document = &s.document;
  options.scene_file = s.file;
  const RunResult r = run_simulation(*s.simulation, *s.schedule, s.observers, options);
  REQUIRE_FALSE(r.completed);
  REQUIRE(r.divergence);
  CHECK(r.divergence->body == "fluid");
  CHECK(r.divergence->particle >= 0);
  CHECK(r.divergence->time > 0.0);
  CHECK(r.divergence->time < 0.5);
  CHECK(r.divergence->step >= 0);
  CHECK_FALSE(r.divergence->reason.empty());
  // The last good state, kept every few steps, is written: a checkpoint of a time before the divergence.
  REQUIRE(r.last_good_written == options.last_good_path);
  const CheckpointHeader header = read_checkpoint_header(options.last_good_path);
  CHECK(header.time < r.divergence->time);
  const Restored restored = restore_from(options.last_good_path);
  CHECK(restored.scene.simulation->time == header.time);
  std::filesystem::remove_all(dir);
}

TEST_CASE("A stable run of the same scene completes", "[run]") {
  LoadedScene s = scene_from(kChannel);
  RunOptions options;
  options.end_time = 0.05;
  const RunResult r = run_simulation(*s.simulation, *s.schedule, s.observers, options);
  CHECK(r.completed);
  CHECK(r.steps.acoustic >= r.steps.advection);
}

TEST_CASE("VTP snapshots are well-formed PolyData with one value per point and component", "[run]") {
  LoadedScene s = scene_from(kChannel);
  const std::string doc = vtp_document(fluid_snapshot(*s.simulation));
  const std::size_t n = s.simulation->fluid().particles.size();
  CHECK(doc.find("<VTKFile type=\"PolyData\"") != std::string::npos);
  CHECK(doc.find("NumberOfPoints=\"" + std::to_string(n) + "\"") != std::string::npos);
  // Every DataArray holds points x components numbers (parsed by hand: std::regex recurses per
  // character and overflows the stack on documents this size under AddressSanitizer).
  int arrays = 0;
  std::size_t at = 0;
  while ((at = doc.find("<DataArray", at)) != std::string::npos) {
    const std::size_t tag_end = doc.find('>', at);
    const std::string tag = doc.substr(at, tag_end - at);
    const std::size_t c = tag.find("NumberOfComponents=\"");
    const std::size_t body_end = doc.find("</DataArray>", tag_end);
    at = body_end;
    if (c == std::string::npos) continue;  // connectivity and offsets of the vertices
    const std::size_t components = std::stoul(tag.substr(c + 20));
    std::istringstream values(doc.substr(tag_end + 1, body_end - tag_end - 1));
    std::size_t count = 0;
    double x;
    while (values >> x) ++count;
    CHECK(count == n * components);
    ++arrays;
  }
  CHECK(arrays == 5);  // points, velocity, pressure, density, vorticity
}

TEST_CASE("How often a run is watched does not change it: outputs and samples never shorten a step", "[run]") {
  // The advection step here is about 0.01 (CFL 0.25, dp 0.05, speed 1 plus the viscous and acoustic
  // criteria); outputs and samples ten times as dense used to cut every step short (reports/pressure.md
  // section 39: the vortex's viscosity moved by 8 % with the output interval).
  auto run = [](Real observer_interval, int samples, std::vector<Real>* sampled) {
    LoadedScene s = scene_from(kChannel);
    RunOptions options;
    options.end_time = 0.2;
    options.observer_interval = observer_interval;
    for (int k = 1; k <= samples; ++k) options.sample_times.push_back(0.001 * k);
    options.on_sample = [sampled](const Simulation& sim) { sampled->push_back(sim.time); };
    const RunResult r = run_simulation(*s.simulation, *s.schedule, s.observers, options);
    REQUIRE(r.completed);
    return std::make_pair(s.simulation->fluid().particles, r.steps.advection);
  };
  std::vector<Real> none, dense;
  const auto [plain, plain_steps] = run(0.0, 0, &none);
  const auto [watched, watched_steps] = run(0.0013, 199, &dense);
  CHECK(watched_steps == plain_steps);
  REQUIRE(watched.size() == plain.size());
  bool identical = true;
  for (std::size_t i = 0; i < plain.size(); ++i)
    identical = identical && watched.pos[i] == plain.pos[i] && watched.vel[i] == plain.vel[i] && watched.rho[i] == plain.rho[i];
  CHECK(identical);
  // Each sample is taken once, after the first step at or past its time, so within one step of it.
  REQUIRE(dense.size() == 199);
  for (std::size_t k = 0; k < dense.size(); ++k) {
    CHECK(dense[k] >= 0.001 * (k + 1) - 1e-12);
    CHECK(dense[k] < 0.001 * (k + 1) + 0.2 / plain_steps * 2.0);
  }
}

TEST_CASE("The fluid option max_advection_step bounds the advection step", "[run]") {
  // The criterion's step here is about 0.01 (dp 0.05, CFL 0.25, speed 1 plus the viscous and
  // acoustic criteria); bounded at 0.002, a run to t = 0.05 takes 25 steps.
  auto steps_to = [](const char* bound) {
    Json doc = Json::parse(kChannel);
    if (bound) doc["fluid"]["max_advection_step"] = Json::parse(bound);
    LoadedScene s = build_scene(doc, "bounded.json");
    RunOptions options;
    options.end_time = 0.05;
    const RunResult r = run_simulation(*s.simulation, *s.schedule, s.observers, options);
    REQUIRE(r.completed);
    return r.steps.advection;
  };
  CHECK(steps_to(nullptr) <= 10);
  const long long bounded = steps_to("0.002");
  CHECK(bounded >= 25);
  CHECK(bounded <= 26);  // the last may be a sliver where the sum of 25 falls short of 0.05 by round-off
}
