// Open boundaries (boundary/open_boundary.hpp): the mass balance of the buffers, checkpoints with a
// changing particle count, and the buffer's rules on small hand-made particle sets.
#include "boundary/open_boundary.hpp"
#include "checkpoint_fixture.hpp"
#include "scene/scene_loader.hpp"
#include "run/checkpoint.hpp"
#include "run/runner.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

using namespace mrsph;

namespace {

const std::filesystem::path kScene = std::filesystem::path(MRSPH_SOURCE_DIR) / "verification/scenes/poiseuille_pressure.json";
// A coarse channel (H / dp = 10) so that the tests run in about a second.
const std::vector<std::string> kCoarse = {"parameters.resolution=10"};

Real ledger_sum(const Simulation& sim) {
  Real sum = 0.0;
  for (const OpenBoundary& b : sim.open_boundaries) sum += b.ledger.mass_into_domain;
  return sum;
}

// A fluid of rho0 = 1, c = 10, dp = 0.1, and an outlet at x = 1 (outward normal +x) with a buffer
// 0.4 deep spanning 0 < y < span_upper, for the buffer's rules on hand-made particle sets.
FluidBody unit_fluid() {
  FluidBody fluid("fluid", 0.1, 1.3);
  fluid.material.eos.rho0 = 1.0;
  fluid.material.eos.c0 = 10.0;
  return fluid;
}

OpenBoundary outlet_at_one(Real span_upper) {
  OpenBoundary outlet;
  outlet.axis = 0;
  outlet.plane = 1.0;
  outlet.side = 1;
  outlet.width = 0.4;
  outlet.span_lower = 0.0;
  outlet.span_upper = span_upper;
  return outlet;
}

}  // namespace

TEST_CASE("Open boundaries: the domain's mass changes by what crosses the planes, to round-off, every step",
          "[open_boundary]") {
  LoadedScene s = load_scene(kScene, kCoarse);
  Simulation& sim = *s.simulation;
  const Real m0 = domain_mass(sim.fluid().particles);
  const Real particle_mass = sim.fluid().particles.mass[0];
  Real worst = 0.0;
  while (sim.time < 3.0) {
    s.schedule->advance(sim, 3.0 - sim.time);
    // Round-off of summing ~300 equal masses: a few ulps of the total.
    worst = std::max(worst, std::abs(domain_mass(sim.fluid().particles) - m0 - ledger_sum(sim)));
  }
  CHECK(worst <= 1e-12 * m0);
  // Not vacuous: the flow carried many columns of particles through both planes (mean speed about
  // 0.6 over 3 time units, 10 particles per column of spacing 0.1).
  for (const OpenBoundary& b : sim.open_boundaries) {
    CHECK(b.ledger.created + b.ledger.deleted > 50);
    CHECK(std::abs(b.ledger.mass_into_domain) > 50 * particle_mass);
  }
  CHECK(sim.open_boundaries[0].ledger.mass_into_domain > 0.0);   // in through the inlet
  CHECK(sim.open_boundaries[1].ledger.mass_into_domain < 0.0);   // out through the outlet
}

TEST_CASE("Open boundaries: a run restarted from a checkpoint equals the uninterrupted one bitwise, "
          "with particles created and deleted on both sides of the checkpoint", "[open_boundary][checkpoint]") {
  const auto dir = std::filesystem::temp_directory_path() / "mrsph_test_open_checkpoint";
  std::filesystem::create_directories(dir);
  const auto options = [](const LoadedScene& s) {
    RunOptions o;
    o.end_time = 3.0;
    o.scene_document = &s.document;
    o.scene_file = s.file;
    return o;
  };
  LoadedScene whole = load_scene(kScene, kCoarse);
  const RunResult uninterrupted = run_simulation(*whole.simulation, *whole.schedule, whole.observers, options(whole));
  REQUIRE(uninterrupted.completed);

  LoadedScene first = load_scene(kScene, kCoarse);
  const auto checkpoint = dir / "checkpoint.bin";
  const RunResult part = run_until_stopped(first, options(first), 1.5, checkpoint);
  REQUIRE(part.interrupted);
  const long long created_before = first.simulation->open_boundaries[0].ledger.created;
  const long long deleted_before = first.simulation->open_boundaries[1].ledger.deleted;
  CHECK(created_before > 0);
  CHECK(deleted_before > 0);

  Restored restored = restore_from(checkpoint);
  LoadedScene& second = restored.scene;
  CHECK(second.simulation->fluid().particles.size() == first.simulation->fluid().particles.size());
  RunOptions o2 = options(second);
  o2.resume = &restored.resume;
  const RunResult rest = run_simulation(*second.simulation, *second.schedule, second.observers, o2);
  REQUIRE(rest.completed);
  CHECK(second.simulation->open_boundaries[0].ledger.created > created_before);
  CHECK(second.simulation->open_boundaries[1].ledger.deleted > deleted_before);

  RunnerState a, b;
  a.series = rest.series;
  b.series = uninterrupted.series;
  CHECK(serialise_checkpoint(second.document, second.file, *second.simulation, a) ==
        serialise_checkpoint(whole.document, whole.file, *whole.simulation, b));
  std::filesystem::remove_all(dir);
}

TEST_CASE("Open boundaries: the exchange moves particles between buffer and domain, deletes beyond the "
          "buffer and refills at the buffer's density", "[open_boundary]") {
  FluidBody fluid = unit_fluid();
  const OpenBoundary outlet = outlet_at_one(0.1);  // one bin
  std::vector<OpenBoundary> boundaries{outlet};
  FluidParticles& f = fluid.particles;
  // One row at y = 0.05: domain particle moved into the buffer (x = 1.01), buffer particles at
  // 1.15 and 1.25, one beyond the far end (1.43), one buffer particle that moved back in (0.99).
  const std::vector<Real> xs = {0.95, 1.01, 1.15, 1.25, 1.43, 0.99};
  f.resize(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) {
    f.pos[i] = Vec2(xs[i], 0.05);
    f.mass[i] = 0.01;
    f.rho[i] = 1.01;                // the buffer's density: spacing m / (rho dp) = 0.099
    f.vel[i] = Vec2(-0.1, 0.0);     // a back-flow through the outlet: the far end empties
  }
  classify_fluid_zones(f, boundaries);
  f.zone[1] = kDomainZone;  // it was in the domain at the last exchange
  f.zone[5] = 1;            // it was in the buffer
  exchange_buffer_particles(fluid, boundaries);
  const OpenBoundaryLedger& l = boundaries[0].ledger;
  CHECK(l.deleted == 1);                                   // the particle at 1.43
  CHECK(l.mass_into_domain == Approx(0.01 - 0.01));        // one out (1.01), one in (0.99)
  // Kept: 0.95, 1.01, 1.15, 1.25, 0.99; refilled behind 1.25 at 1.349 (1.448 would pass the far end 1.4).
  REQUIRE(f.size() == 6);
  CHECK(l.created == 1);
  CHECK(f.pos[5].x() == Approx(1.25 + 0.01 / (1.01 * 0.1)));
  CHECK(f.zone[1] == 1);
  CHECK(f.zone[4] == kDomainZone);  // the old particle 5 (0.99), now fifth
  CHECK(f.pos[4].x() == Approx(0.99));

  // Flowing out, the buffer's far end is where particles leave: nothing is made there.
  for (Vec2& v : f.vel) v = Vec2(0.1, 0.0);
  f.pos[5].x() = 1.45;  // the refilled particle has left
  exchange_buffer_particles(fluid, boundaries);
  CHECK(boundaries[0].ledger.created == 1);
  CHECK(boundaries[0].ledger.deleted == 2);
  CHECK(f.size() == 5);
}

TEST_CASE("The equation of state's background pressure is the pressure at rest, and density inverts pressure",
          "[open_boundary][eos]") {
  for (EquationOfStateKind kind : {EquationOfStateKind::Linear, EquationOfStateKind::Tait}) {
    EquationOfState eos;
    eos.kind = kind;
    eos.rho0 = 1000.0;
    eos.c0 = 10.0;
    eos.background = 1333.0;
    CHECK(eos.pressure(eos.rho0) == Approx(1333.0));
    CHECK(eos.density(1333.0) == Approx(1000.0));
    // (within the Tait law's range: p - p_b > -rho0 c^2 / 7)
    for (double p : {-10000.0, 0.0, 500.0, 40000.0}) CHECK(eos.pressure(eos.density(p)) == Approx(p).margin(1e-9));
    // the pressure differences, which drive the flow, do not depend on the background
    EquationOfState none = eos;
    none.background = 0.0;
    CHECK(eos.pressure(1010.0) - eos.pressure(1000.0) == Approx(none.pressure(1010.0) - none.pressure(1000.0)));
  }
}

TEST_CASE("A pressure boundary with a total entering pressure: Bernoulli's static pressure where fluid enters, "
          "p_b where it leaves", "[open_boundary]") {
  // One bin of an outlet at x = 1 (outward normal +x), p_b = 5, rho0 = 1: a domain particle in the
  // band and a buffer particle 0.1 beyond the plane, the domain's pressure p_b (slope zero).
  const auto buffer_pressure = [](Real u, bool total) {
    FluidBody fluid = unit_fluid();
    OpenBoundary outlet = outlet_at_one(0.1);
    outlet.pressure = [](Real) { return 5.0; };
    outlet.total_pressure_inflow = total;
    std::vector<OpenBoundary> boundaries{outlet};
    FluidParticles& f = fluid.particles;
    f.resize(2);
    f.pos[0] = Vec2(0.95, 0.05);
    f.pos[1] = Vec2(1.10, 0.05);
    for (std::size_t i = 0; i < 2; ++i) {
      f.mass[i] = 0.01;
      f.rho[i] = 1.0;
      f.p[i] = 5.0;
      f.vel[i] = Vec2(u, 0.0);
    }
    classify_fluid_zones(f, boundaries);
    impose_buffer_states(fluid, boundaries, 0.0, 0.0);
    // The buffer pressure is p at the plane continued with the slope through (0, p_plane) and the
    // domain particle (depth -0.05, p = 5): read p at the plane back from the two.
    const Real slope = (f.p[1] - 5.0) / (0.10 + 0.05);
    return f.p[1] - slope * 0.10;
  };
  // Entering at 2 (u_n = -2): p_b - rho0 u^2 / 2 = 5 - 2 = 3 at the plane; leaving, or static: p_b.
  CHECK(buffer_pressure(-2.0, true) == Approx(3.0));
  CHECK(buffer_pressure(+2.0, true) == Approx(5.0));
  CHECK(buffer_pressure(-2.0, false) == Approx(5.0));
}

TEST_CASE("A pressure boundary's smoothed normal velocity holds a parabolic profile exactly and not a streak "
          "one bin wide", "[open_boundary]") {
  // An outlet at x = 1 across a channel 0 < y < 1 (ten bins of dp = 0.1): band particles in two
  // columns (x = 0.95, 0.85) at every bin centre, one buffer particle per bin at x = 1.1.
  const auto buffer_velocity = [](bool smooth, Real streak) {
    FluidBody fluid = unit_fluid();
    OpenBoundary outlet = outlet_at_one(1.0);
    outlet.pressure = [](Real) { return 0.0; };
    outlet.smooth_normal_velocity = smooth;
    std::vector<OpenBoundary> boundaries{outlet};
    FluidParticles& f = fluid.particles;
    f.resize(30);
    for (int k = 0; k < 10; ++k) {
      const Real y = 0.05 + 0.1 * k;
      const Real u = 4.0 * y * (1.0 - y) + (k == 6 ? streak : 0.0);
      for (int c = 0; c < 3; ++c) {
        const std::size_t i = 3 * k + c;
        f.pos[i] = Vec2(c == 2 ? 1.1 : 0.95 - 0.1 * c, y);
        f.mass[i] = 0.01;
        f.rho[i] = 1.0;
        f.vel[i] = Vec2(u, 0.0);
      }
    }
    classify_fluid_zones(f, boundaries);
    impose_buffer_states(fluid, boundaries, 0.0, 0.0);
    std::vector<Real> u_buffer;
    for (int k = 0; k < 10; ++k) u_buffer.push_back(f.vel[3 * k + 2].x());
    return u_buffer;
  };
  const std::vector<Real> profile = buffer_velocity(true, 0.0);
  for (int k = 0; k < 10; ++k) {
    const Real y = 0.05 + 0.1 * k;
    CHECK(profile[k] == Approx(4.0 * y * (1.0 - y)).margin(1e-12));
  }
  // A streak of 1 in bin 6: the bins' means pass it whole; the polynomial keeps a fraction spread
  // over its neighbours (5 terms over 10 bins: at most about half).
  const std::vector<Real> by_bins = buffer_velocity(false, 1.0);
  const std::vector<Real> smoothed = buffer_velocity(true, 1.0);
  const Real parabola_6 = 4.0 * 0.65 * 0.35;
  CHECK(by_bins[6] - parabola_6 == Approx(1.0));
  CHECK(smoothed[6] - parabola_6 < 0.6);
  CHECK(smoothed[6] - parabola_6 > 0.0);
}
