#include "boundary/womersley_profile.hpp"
#include "fluid/acoustic_step.hpp"
#include "fluid/advection_pair_terms.hpp"
#include "fluid/density_summation.hpp"
#include "fluid/reference_pressure.hpp"
#include "fluid/transport_velocity.hpp"
#include "fluid/viscous_force.hpp"
#include "fluid/wall_rules.hpp"
#include "fsi/fluid_solid_coupling.hpp"
#include "scene_fixture.hpp"
#include "run/runner.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <functional>
#include <random>
#include <tuple>

using namespace mrsph;

namespace {

std::string periodic_box(const std::string& fluid_extra = "", const std::string& extra = "") {
  return R"({
    "parameters": {"dp": 0.05},
    "domain": {"lower": [0, 0], "upper": [1, 1], "periodic": [true, true]},
    "fluid": {"dp": "dp", "region": {"rectangle": {"lower": [0, 0], "upper": [1, 1]}},
              "density": 1, "sound_speed": 10)" + fluid_extra + R"(},
    "end_time": 0.2)" + extra + "}";
}

// The fluid on 0 < y < 1 between a floor and a lid, periodic in x, viscosity 0.3; fluid_extra: more
// fluid keys (",\"key\": value ...").
std::string walled_channel_with(const std::string& fluid_extra) {
  return R"json({
    "parameters": {"dp": 0.05},
    "domain": {"lower": [0, -0.25], "upper": [1, 1.25], "periodic": [true, false]},
    "fluid": {"dp": "dp", "region": {"rectangle": {"lower": [0, 0], "upper": [1, 1]}},
              "density": 1, "sound_speed": 10, "viscosity": 0.3)json" + fluid_extra + R"json(},
    "walls": [{"name": "floor", "dp": "dp", "region": {"rectangle": {"lower": [0, -0.2], "upper": [1, 0]}}},
              {"name": "lid", "dp": "dp", "region": {"rectangle": {"lower": [0, 1], "upper": [1, 1.2]}}}],
    "end_time": 1})json";
}

// The same channel with the viscous wall rule `rule` (fluid.viscous_wall_velocity).
std::string walled_channel(const std::string& rule) { return walled_channel_with(R"(, "viscous_wall_velocity": ")" + rule + "\""); }

Vec2 fluid_momentum(const Simulation& sim) {
  const FluidParticles& f = sim.fluid().particles;
  Vec2 m = Vec2::Zero();
  for (std::size_t i = 0; i < f.size(); ++i) m += f.mass[i] * f.vel[i];
  return m;
}

}  // namespace

TEST_CASE("Density summation gives rho0 on a full lattice, next to walls too", "[fluid]") {
  LoadedScene s = scene_from(R"({
    "parameters": {"dp": 0.05},
    "domain": {"lower": [0, -0.3], "upper": [1, 1.3], "periodic": [true, false]},
    "fluid": {"dp": "dp", "region": {"rectangle": {"lower": [0, 0], "upper": [1, 1]}}, "density": 1000, "sound_speed": 10},
    "walls": [{"name": "bottom", "dp": "dp", "region": {"rectangle": {"lower": [0, -0.2], "upper": [1, 0]}}},
              {"name": "top", "dp": "dp", "region": {"rectangle": {"lower": [0, 1], "upper": [1, 1.2]}}}],
    "end_time": 1})");
  const FluidParticles& f = s.simulation->fluid().particles;
  for (std::size_t i = 0; i < f.size(); ++i) REQUIRE(f.rho[i] == Approx(1000.0).epsilon(1e-12));
}

TEST_CASE("A relaxed re-initialisation moves the density by its fraction towards the summation", "[fluid]") {
  // On a full periodic lattice the summation is rho0 = 1 exactly (the test above). A checkerboard of
  // +-1 % in the carried density is pulled a quarter of the way back with relaxation 0.25, all the
  // way with 1 (the paper's), and the volumes follow the density.
  LoadedScene s = scene_from(periodic_box(R"(, "density_relaxation": 0.25)"));
  FluidBody& fluid = s.simulation->fluid();
  FluidParticles& f = fluid.particles;
  auto checkerboard = [&](std::size_t i) {
    return (std::lround(f.pos[i].x() / 0.05 - 0.5) + std::lround(f.pos[i].y() / 0.05 - 0.5)) % 2 == 0 ? 1.0 : -1.0;
  };
  for (std::size_t i = 0; i < f.size(); ++i) f.rho[i] = 1.0 + 0.01 * checkerboard(i);
  reinitialise_density(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), fluid.options.density_relaxation);
  for (std::size_t i = 0; i < f.size(); ++i) {
    REQUIRE(f.rho[i] == Approx(1.0 + 0.0075 * checkerboard(i)).epsilon(1e-12));
    REQUIRE(f.vol[i] == Approx(f.mass[i] / f.rho[i]).epsilon(1e-14));
  }
  reinitialise_density(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), 1.0);
  for (std::size_t i = 0; i < f.size(); ++i) REQUIRE(f.rho[i] == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("The summation's reset per unit time does not depend on an advection CFL below the paper's", "[fluid]") {
  // The checkerboard above, reset once by the schedules' relaxation per step at CFL 0.0625, 0.25 and
  // 0.5: a quarter of the way back in a quarter of the step, all the way at the paper's CFL and above
  // (reports/pressure.md section 41); a relaxed option is scaled alike.
  const auto reset = [](double cfl, double relaxation) {
    LoadedScene s = scene_from(periodic_box(fmt::format(R"(, "advection_cfl": {}, "density_relaxation": {})", cfl, relaxation)));
    FluidBody& fluid = s.simulation->fluid();
    FluidParticles& f = fluid.particles;
    for (std::size_t i = 0; i < f.size(); ++i)
      f.rho[i] = 1.0 + 0.01 * ((std::lround(f.pos[i].x() / 0.05 - 0.5) + std::lround(f.pos[i].y() / 0.05 - 0.5)) % 2 == 0 ? 1.0 : -1.0);
    RealArray before = f.rho;
    reinitialise_density(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), density_relaxation_per_step(fluid.options));
    double largest_ratio = 0.0, smallest_ratio = 2.0;
    for (std::size_t i = 0; i < f.size(); ++i) {  // the fraction of the way to the summation's 1
      const double ratio = (before[i] - f.rho[i]) / (before[i] - 1.0);
      largest_ratio = std::max(largest_ratio, ratio);
      smallest_ratio = std::min(smallest_ratio, ratio);
    }
    return std::pair{smallest_ratio, largest_ratio};
  };
  for (const auto& [cfl, relaxation, expected] : {std::tuple{0.0625, 1.0, 0.25}, std::tuple{0.25, 1.0, 1.0},
                                                  std::tuple{0.5, 1.0, 1.0}, std::tuple{0.125, 0.2, 0.1}}) {
    const auto [lo, hi] = reset(cfl, relaxation);
    INFO("CFL " << cfl << ", relaxation " << relaxation);
    CHECK(lo == Approx(expected).epsilon(1e-9));  // the summation is 1 to 1e-12 (the test above)
    CHECK(hi == Approx(expected).epsilon(1e-9));
  }
}

TEST_CASE("The viscous operator is exact for a quadratic field on a lattice (with the lattice correction)", "[fluid]") {
  for (bool corrected : {true, false}) {
    LoadedScene s = scene_from(periodic_box(R"(, "viscosity": 0.3, "viscous_lattice_correction": )" +
                                            std::string(corrected ? "true" : "false")));
    Simulation& sim = *s.simulation;
    FluidParticles& f = sim.fluid().particles;
    // u = y^2 / 2 has Laplacian 1; use only particles whose whole support avoids the periodic seam.
    for (std::size_t i = 0; i < f.size(); ++i) f.vel[i] = Vec2(0.5 * f.pos[i].y() * f.pos[i].y(), 0.0);
    compute_viscous_force(sim.fluid(), sim.fluid_inner(), sim.fluid_contacts(), Vec2::Zero());
    const double h = sim.fluid().h();
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (f.pos[i].y() < 2.5 * h || f.pos[i].y() > 1.0 - 2.5 * h) continue;
      const double laplacian = f.force_prior[i].x() / (0.3 * f.vol[i]);
      if (corrected) REQUIRE(laplacian == Approx(1.0).epsilon(1e-10));
      else REQUIRE(laplacian == Approx(0.9638).epsilon(1e-3));  // METHOD.md's operator, 3.6 % low
      REQUIRE(std::abs(f.force_prior[i].y()) < 1e-9);
    }
  }
}

TEST_CASE("A closed fluid conserves momentum to round-off", "[fluid]") {
  LoadedScene s = scene_from(periodic_box(R"(, "viscosity": 0.01, "riemann": {"continuity": true, "momentum": true},
                                              "transport_velocity_alpha": 0.25)"));
  Simulation& sim = *s.simulation;
  FluidParticles& f = sim.fluid().particles;
  std::mt19937 gen(11);
  std::normal_distribution<double> noise(0.0, 0.3);
  for (auto& v : f.vel) v = Vec2(1.0 + noise(gen), noise(gen));
  const Vec2 before = fluid_momentum(sim);
  for (int k = 0; k < 60; ++k) s.schedule->advance(sim, 1.0);
  const Vec2 after = fluid_momentum(sim);
  const double scale = 0.3 * std::sqrt(double(f.size())) * f.mass[0];  // size of the random momenta
  CHECK((after - before).norm() / before.norm() < 1e-12);
  CHECK((after - before).norm() / scale < 1e-12);
}

TEST_CASE("A water column holds the hydrostatic pressure on average", "[fluid]") {
  // Tank 0.3 m wide, water 0.2 m deep, gravity 9.81; c = 10 sqrt(2 g H) (CASES.md rule). Started at
  // uniform density, the column compresses and "breathes" acoustically; the Riemann limiter damps
  // that only slowly, so the check is on the time-mean pressure over [0.5, 3] s.
  LoadedScene s = scene_from(R"json({
    "parameters": {"dp": 0.01, "H": 0.2, "g": 9.81},
    "domain": {"lower": [-0.05, -0.05], "upper": [0.35, 0.35]},
    "fluid": {"dp": "dp", "region": {"rectangle": {"lower": [0, 0], "upper": [0.3, "H"]}}, "density": 1000,
              "sound_speed": "10 * sqrt(2 * g * H)", "density_reinitialisation": "free_surface",
              "riemann": {"continuity": true, "momentum": true}},
    "walls": [{"name": "tank", "dp": "dp", "region": {"difference": {
                "base": {"rectangle": {"lower": ["-4*dp", "-4*dp"], "upper": ["0.3+4*dp", 0.3]}},
                "subtract": [{"rectangle": {"lower": [0, 0], "upper": [0.3, 0.4]}}]}}}],
    "body_force": {"constant": [0, "-g"]},
    "observers": [{"name": "mid", "body": "fluid", "point": [0.15, 0.1], "quantity": "pressure"}],
    "end_time": 3.0})json");
  RunOptions options;
  options.end_time = 3.0;
  options.observer_interval = 0.005;
  const RunResult r = run_simulation(*s.simulation, *s.schedule, s.observers, options);
  REQUIRE(r.completed);
  double sum = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < r.series[0].time.size(); ++k)
    if (r.series[0].time[k] > 0.5) { sum += r.series[0].values[k][0]; ++n; }
  // rho g (H - y) = 981 Pa at mid-depth. A free surface's defaults divide the pressure force by the
  // first moment of the column's own arrangement (without it the column would hold itself up with
  // 981 / M1; with the square lattice's M1 = 0.974 on a column that settles to 0.986, 1.2 % low),
  // continue the rest state into the walls and filter the summation's noise (reports/pressure.md
  // sections 14 and 18: 976 Pa here). 1 %: issue 17's accuracy target for the still tank; the
  // breathing is damped by t = 0.5 s.
  CHECK(sum / n == Approx(1000 * 9.81 * 0.1).epsilon(0.01));
  double top = 0.0;
  for (const auto& p : s.simulation->fluid().particles.pos) top = std::max(top, p.y());
  CHECK(top < 0.2 + 0.01);  // no particle thrown off the free surface
}

TEST_CASE("Initial relaxation fills the voids a slanted wall leaves in the fluid lattice", "[fluid]") {
  // A channel with its lower wall cut at 30 degrees: the fluid lattice as cut leaves gaps of up to
  // a spacing against the slanted wall, and the density summation shows them as deficits. After
  // the relaxation the worst deficit must be much smaller, no particle may have entered the wall,
  // and the velocities are the initial field at the relaxed positions.
  const auto scene = [](int steps) {
    return scene_from(R"({
      "parameters": {"dp": 0.05, "t": 0.5773502691896257},
      "domain": {"lower": [0, -0.3], "upper": [2, 1.3], "periodic": [true, false]},
      "fluid": {"dp": "dp", "density": 1000, "sound_speed": 10, "relaxation_steps": )" + std::to_string(steps) + R"(,
                "initial_velocity": {"type": "womersley", "bottom": 0, "height": 1, "pressure_gradient_amplitude": 1,
                                     "angular_frequency": 6.283185307179586, "density": 1000, "kinematic_viscosity": 0.01,
                                     "time": 0.1},
                "region": {"difference": {"base": {"rectangle": {"lower": [0, 0], "upper": [2, 1]}},
                           "subtract": [{"polygon": {"vertices": [[0.5, 0], [1.5, 0], [1.5, "t"]]}}]}}},
      "walls": [{"name": "floor", "dp": "dp", "region": {"union": [
                   {"rectangle": {"lower": [0, -0.2], "upper": [2, 0]}},
                   {"polygon": {"vertices": [[0.5, 0], [1.5, 0], [1.5, "t"]]}}]}},
                {"name": "lid", "dp": "dp", "region": {"rectangle": {"lower": [0, 1], "upper": [2, 1.2]}}}],
      "end_time": 1})");
  };
  const auto worst_deficit = [](const LoadedScene& s) {
    double worst = 0.0;
    for (double rho : s.simulation->fluid().particles.rho) worst = std::max(worst, 1.0 - rho / 1000.0);
    return worst;
  };
  const LoadedScene cut = scene(0), relaxed = scene(100);
  const double before = worst_deficit(cut), after = worst_deficit(relaxed);
  INFO("worst density deficit: as cut " << before << ", relaxed " << after);
  REQUIRE(before > 0.05);        // the test is only meaningful if the cut lattice has voids
  REQUIRE(after < 0.5 * before);
  const FluidParticles& f = relaxed.simulation->fluid().particles;
  WomersleyProfile profile;  // the scene's initial velocity field
  profile.channel_height = 1.0;
  profile.pressure_gradient_amplitude = 1.0;
  profile.angular_frequency = 6.283185307179586;
  profile.density = 1000.0;
  profile.kinematic_viscosity = 0.01;
  // Inside the wall's region by less than half a spacing (where the wall's first particles sit; at
  // the ramp's acute tip the region is thinner than a spacing and has no particles).
  const double slope = 0.5773502691896257, cos30 = 0.8660254037844386, half_dp = 0.025;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Vec2& p = f.pos[i];
    REQUIRE(p.y() > -half_dp);
    if (p.x() > 0.5 && p.x() < 1.5) REQUIRE((slope * (p.x() - 0.5) - p.y()) * cos30 < half_dp);
    REQUIRE(f.vel[i].x() == Approx(profile.velocity(p.y(), 0.1)).epsilon(1e-12));  // u(y) at the relaxed y
    REQUIRE(f.vel[i].y() == 0.0);
  }
}

TEST_CASE("The compressibility record keeps the largest density deviation and Mach number, with where and when", "[fluid]") {
  LoadedScene s = scene_from(periodic_box());
  Simulation& sim = *s.simulation;
  FluidParticles& f = sim.fluid().particles;
  const double rho0 = sim.fluid().material.rho0(), c0 = sim.fluid().material.sound_speed();
  CompressibilityRecord record;
  update_compressibility_record(sim, record);
  CHECK(record.density_deviation.value < 1e-12);  // the lattice at rest starts at rho0
  CHECK(record.mach.value == 0.0);

  sim.time = 0.5;
  f.rho[3] = 0.8 * rho0;                 // a 20 % deficit
  f.rho[7] = 1.1 * rho0;                 // a smaller excess
  f.vel[5] = Vec2(0.3 * c0, 0.4 * c0);   // Mach 0.5
  update_compressibility_record(sim, record);
  CHECK(record.density_deviation.value == Approx(0.2));
  CHECK(record.density_deviation.time == 0.5);
  CHECK(record.density_deviation.position == f.pos[3]);
  CHECK(record.mach.value == Approx(0.5));
  CHECK(record.mach.position == f.pos[5]);

  sim.time = 0.7;  // milder later: the record keeps the earlier extremes
  f.rho[3] = rho0;
  f.vel[5] = Vec2(0.1 * c0, 0.0);
  update_compressibility_record(sim, record);
  CHECK(record.density_deviation.time == 0.5);
  CHECK(record.mach.value == Approx(0.5));
  f.vel[9] = Vec2(0.0, -0.6 * c0);  // a faster one replaces it
  update_compressibility_record(sim, record);
  CHECK(record.mach.value == Approx(0.6));
  CHECK(record.mach.time == 0.7);
  CHECK(record.mach.position == f.pos[9]);
}

TEST_CASE("The boundary impulses recorded over one or several advection steps close the fluid's momentum balance to round-off", "[fluid]") {
  // A periodic channel with a cylinder, driven by a body force: over each advection step, and over
  // several, the fluid's momentum changes by the body force's impulse minus what it gave the walls
  // and the cylinder, and the force observer reports that impulse over the record's duration (drag
  // and lift as momentum actually transferred, not the force of the step's last acoustic sub-step).
  // The pair forces are measured from the fluid's mean pressure (a confined fluid): that constant
  // must not break the balance.
  LoadedScene s = scene_from(R"({
    "parameters": {"dp": 0.1},
    "domain": {"lower": [0, -0.5], "upper": [4, 2.5], "periodic": [true, false]},
    "fluid": {"dp": "dp", "region": {"difference": {"base": {"rectangle": {"lower": [0, 0], "upper": [4, 2]}},
                                                    "subtract": [{"circle": {"center": [2, 1], "radius": 0.3}}]}},
              "density": 1, "sound_speed": 10, "viscosity": 0.02, "transport_velocity_alpha": 0.25,
              "riemann": {"continuity": true, "momentum": true}},
    "walls": [{"name": "floor", "dp": "dp", "region": {"rectangle": {"lower": [0, -0.4], "upper": [4, 0]}}},
              {"name": "lid", "dp": "dp", "region": {"rectangle": {"lower": [0, 2], "upper": [4, 2.4]}}},
              {"name": "cylinder", "dp": "dp", "region": {"circle": {"center": [2, 1], "radius": 0.3}},
               "fill": {"pattern": "rings", "center": [2, 1], "radius": 0.3}}],
    "body_force": {"constant": [0.5, 0]},
    "end_time": 1})");
  Simulation& sim = *s.simulation;
  REQUIRE(sim.fluid().options.pressure_reference == PressureReference::Mean);
  for (FluidContact& c : sim.fluid_contacts()) c.records_impulse = true;  // as the runner does for observed ones
  const FluidParticles& f = sim.fluid().particles;
  double mass = 0.0;
  for (double m : f.mass) mass += m;
  const Vec2 g(0.5, 0.0);
  double largest_impulse = 0.0, worst_residual = 0.0;
  // The record spans one advection step, then three (an observer interval over several steps): the
  // runner clears it after each record, here at the start of each span.
  for (int span = 0; span < 20; ++span) {
    const Vec2 before = fluid_momentum(sim);
    const double t0 = sim.time;
    clear_boundary_impulses(sim.fluid_contacts());
    for (int step = 0; step < (span < 10 ? 1 : 3); ++step) s.schedule->advance(sim, 1.0);
    Vec2 given = Vec2::Zero();
    for (const FluidContact& c : sim.fluid_contacts()) {
      REQUIRE(c.recorded_duration == Approx(sim.time - t0).epsilon(1e-12));
      given += c.recorded_impulse;
    }
    const Vec2 residual = fluid_momentum(sim) - before - (g * mass * (sim.time - t0) - given);
    largest_impulse = std::max(largest_impulse, given.norm());
    worst_residual = std::max(worst_residual, residual.norm());
  }
  INFO("largest boundary impulse of a span " << largest_impulse << ", worst residual " << worst_residual);
  REQUIRE(largest_impulse > 1e-4);  // the walls and the cylinder do take momentum
  CHECK(worst_residual < 1e-12 * mass);
}

TEST_CASE("In steady plane Poiseuille flow the walls take the body force, all of it through the viscous part", "[fluid]") {
  // Periodic channel, H = 1, driven by g = 0.8 with nu = 0.1, started from its steady profile
  // u = g y (H - y) / (2 nu): the walls take the body force's momentum rho g V, and by the channel's
  // periodicity the pressure pushes only across them, so the force observer's viscous part is all of it.
  LoadedScene s = scene_from(R"json({
    "parameters": {"dp": 0.05},
    "domain": {"lower": [0, -0.2], "upper": [1, 1.2], "periodic": [true, false]},
    "fluid": {"dp": "dp", "region": {"rectangle": {"lower": [0, 0], "upper": [1, 1]}},
              "density": 1, "sound_speed": 10, "viscosity": 0.1, "transport_velocity_alpha": 0.25,
              "initial_velocity": {"type": "expression", "u": "4 * y * (1 - y)", "v": "0"}},
    "walls": [{"name": "floor", "dp": "dp", "region": {"rectangle": {"lower": [0, -0.2], "upper": [1, 0]}}},
              {"name": "lid", "dp": "dp", "region": {"rectangle": {"lower": [0, 1], "upper": [1, 1.2]}}}],
    "body_force": {"constant": [0.8, 0]},
    "end_time": 1})json");
  Simulation& sim = *s.simulation;
  for (int step = 0; step < 20; ++step) s.schedule->advance(sim, 1.0);
  Vec2 total = Vec2::Zero(), viscous = Vec2::Zero();
  for (const FluidContact& c : sim.fluid_contacts()) {
    total += total_force_on_boundary(c);
    viscous += viscous_force_on_boundary(c);
  }
  const double body_force = 0.8 * 1.0 * 1.0;  // rho g V
  INFO("wall force " << total.transpose() << ", viscous part " << viscous.transpose());
  // The wall rule is exact in total for a linear shear (the no-slip mirror on a lattice), and the
  // viscous operator, with its lattice correction, exact for the quadratic profile inside: what is
  // left is the first layers' quadratic term, of order dp / H = 5 % times the share of the wall's
  // support in the profile's curvature; 3 % bounds it.
  CHECK(viscous.x() == Approx(body_force).epsilon(0.03));
  CHECK(std::abs(total.x() - viscous.x()) < 0.01 * body_force);  // pressure: across the walls only
}

TEST_CASE("The viscous wall rule continues a linear shear into the wall exactly; the paper's mirror does not", "[fluid]") {
  // u = y over a resting floor (y < 0 is wall): the Laplacian is zero, so the lattice-corrected
  // operator must give no force on the rows next to the floor. The continuation gives each dummy
  // particle -d_a, the mirror -y_i whatever its depth: the first row gets too little shear from the
  // deeper dummies, the second too much (a slip of order dp; reports/pressure.md section 20).
  for (const std::string rule : {"extrapolated", "mirrored"}) {
    LoadedScene s = scene_from(walled_channel(rule));
    Simulation& sim = *s.simulation;
    FluidParticles& f = sim.fluid().particles;
    for (std::size_t i = 0; i < f.size(); ++i) f.vel[i] = Vec2(f.pos[i].y(), 0.0);
    compute_viscous_force(sim.fluid(), sim.fluid_inner(), sim.fluid_contacts(), Vec2::Zero());
    const double h = sim.fluid().h(), shear_over_dp = 1.0 / 0.05;
    double largest = 0.0;  // the operator's Laplacian of u on the rows within the floor's reach
    for (std::size_t i = 0; i < f.size(); ++i)
      if (f.pos[i].y() < 2.0 * h) largest = std::max(largest, std::abs(f.force_prior[i].x()) / (0.3 * f.vol[i]));
    INFO(rule << ": largest |Laplacian| next to the floor " << largest << ", shear / dp " << shear_over_dp);
    if (rule == "extrapolated") CHECK(largest < 1e-9 * shear_over_dp);  // round-off: the sums are exact
    else CHECK(largest > 0.01 * shear_over_dp);  // 0.036 shear / dp on the first row at h = 1.3 dp
  }
}

TEST_CASE("The quadratic viscous wall rule continues a body-force-driven parabola into the wall exactly; the linear one slips", "[fluid]") {
  // u = U y (1 - y) between a floor at y = 0 and a lid at y = 1, driven by b = 2 nu U along the
  // periodic x: the steady channel's profile (Poiseuille). The wall's momentum balance gives the
  // curvature nu u'' = -b, and the quadratic rule continues u into the walls as that parabola: the
  // lattice-corrected operator then returns u'' = -2 U on the rows next to the walls as in the bulk.
  // The linear continuation gives each dummy U d_a (d_i + d_a) too much (wall_rules.hpp): a slip, its
  // Laplacian there short by a sizeable fraction of 2 U.
  const double U = 1.0, nu = 0.3, b = 2.0 * nu * U;
  for (const std::string rule : {"quadratic", "extrapolated"}) {
    LoadedScene s = scene_from(walled_channel(rule));
    Simulation& sim = *s.simulation;
    FluidParticles& f = sim.fluid().particles;
    for (std::size_t i = 0; i < f.size(); ++i) f.vel[i] = Vec2(U * f.pos[i].y() * (1.0 - f.pos[i].y()), 0.0);
    std::fill(f.pressure_force.begin(), f.pressure_force.end(), Vec2::Zero());  // no pressure gradient
    compute_viscous_force(sim.fluid(), sim.fluid_inner(), sim.fluid_contacts(), Vec2(b, 0.0));
    const double h = sim.fluid().h();
    double largest = 0.0;  // |operator's Laplacian of u - u''| on the rows within a wall's reach
    for (std::size_t i = 0; i < f.size(); ++i) {
      const double y = f.pos[i].y();
      if (y < 2.0 * h || y > 1.0 - 2.0 * h)
        largest = std::max(largest, std::abs(f.force_prior[i].x() / (0.3 * f.vol[i]) + 2.0 * U));
    }
    INFO(rule << ": largest |Laplacian - u''| next to the walls " << largest << ", u'' = " << -2.0 * U);
    if (rule == "quadratic") CHECK(largest < 1e-9 * 2.0 * U);  // round-off: the continuation is the parabola
    else CHECK(largest > 0.05 * 2.0 * U);
  }
}

TEST_CASE("delta-SPH diffusion vanishes on a linear density, at a free surface too, and damps particle-scale noise", "[fluid]") {
  // Antuono et al. (2010): the corrected term is zero pair by pair for a density linear in space,
  // so a hydrostatic column is not diffused; the plain term of Molteni & Colagrossi would be
  // 2 delta h c0 |grad rho| |dW| V per pair there.
  SECTION("a linear density on a block with free edges (truncated supports on every side)") {
    LoadedScene s = scene_from(R"({
      "parameters": {"dp": 0.05},
      "domain": {"lower": [-1, -1], "upper": [2, 2]},
      "fluid": {"dp": "dp", "region": {"rectangle": {"lower": [0, 0], "upper": [1, 1]}}, "density": 1000,
                "sound_speed": 10, "delta_sph": 0.1, "density_reinitialisation": "none"},
      "end_time": 1})");
    FluidBody& fluid = s.simulation->fluid();
    FluidParticles& f = fluid.particles;
    for (std::size_t i = 0; i < f.size(); ++i) f.rho[i] = 1000.0 + 5.0 * f.pos[i].x() - 3.0 * f.pos[i].y();
    compute_pressure_interaction(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), Vec2::Zero());
    // Scale of one plain pair term: delta h c0 2 |grad rho| |dW| V ~ 0.1 * 0.065 * 10 * 2 * 5.8 * 40 * 0.0025.
    for (std::size_t i = 0; i < f.size(); ++i) REQUIRE(std::abs(f.drho_dt[i]) < 1e-10);
  }
  SECTION("a checkerboard perturbation in a periodic box: every particle's density moves towards the mean") {
    LoadedScene s = scene_from(periodic_box(R"(, "delta_sph": 0.1, "density_reinitialisation": "none")"));
    FluidBody& fluid = s.simulation->fluid();
    FluidParticles& f = fluid.particles;
    std::vector<int> sign(f.size());
    for (std::size_t i = 0; i < f.size(); ++i) {
      const long cell = std::lround(f.pos[i].x() / 0.05 - 0.5) + std::lround(f.pos[i].y() / 0.05 - 0.5);
      sign[i] = cell % 2 == 0 ? 1 : -1;
      f.rho[i] = 1.0 + 0.001 * sign[i];
    }
    compute_pressure_interaction(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), Vec2::Zero());
    double balance = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      REQUIRE(f.drho_dt[i] * sign[i] < 0.0);
      balance += f.vol[i] * f.drho_dt[i];  // the volumes the operator used
      scale += std::abs(f.vol[i] * f.drho_dt[i]);
    }
    CHECK(std::abs(balance) < 1e-12 * scale);  // sum V_i D_i = 0 by the pair antisymmetry (to round-off)
  }
}

TEST_CASE("The internal energy of each equation of state has de/drho = p / rho^2 and vanishes at rho0", "[fluid]") {
  for (EquationOfStateKind kind : {EquationOfStateKind::Linear, EquationOfStateKind::Tait}) {
    EquationOfState eos{kind, 1000.0, 20.0, 7.0, 3924.0};
    CHECK(eos.internal_energy(1000.0) == 0.0);
    for (double rho : {990.0, 1000.0, 1013.0}) {
      const double step = 1e-3;
      const double derivative = (eos.internal_energy(rho + step) - eos.internal_energy(rho - step)) / (2.0 * step);
      CHECK(derivative == Approx(eos.pressure(rho) / (rho * rho)).epsilon(1e-6));
    }
  }
}

namespace {

// A doubly periodic box under a background pressure of 1 % of rho c^2 (the still tank's 2 rho g H),
// no viscosity and no Riemann terms, started from a square lattice with a 3 cm/s particle-scale
// velocity field: kinetic plus internal energy after `steps` advection steps, minus at the start.
double energy_change_under_pressure(bool refresh_pair_geometry, int steps, double& initial_kinetic) {
  LoadedScene s = scene_from(R"json({
    "parameters": {"dp": 0.005, "c": 19.81},
    "domain": {"lower": [0, 0], "upper": [0.1, 0.1], "periodic": [true, true]},
    "fluid": {"dp": "dp", "region": {"rectangle": {"lower": [0, 0], "upper": [0.1, 0.1]}}, "density": 1000,
              "sound_speed": "c", "reference_velocity": "c / 10", "background_pressure": "0.01 * 1000 * c^2",
              "density_reinitialisation": "internal", "pressure_reference": "zero",
              "riemann": {"continuity": false, "momentum": false}, "refresh_pair_geometry": )json" +
                             std::string(refresh_pair_geometry ? "true" : "false") + R"json(,
              "initial_velocity": {"type": "expression", "u": "0.03*sin(2345.6*x+1771.3*y)", "v": "0.03*sin(1917.1*x-2553.7*y)"}},
    "schedule": {"acoustic_steps": "equal_split"},
    "end_time": 1})json");
  // Equal acoustic steps: 50 advection steps are 0.04 s, the horizon the bounds below were measured
  // on (with full steps 50 are 0.049 s, where the refreshed run's change is -5.5 %, and -4.8 % with
  // equal steps over 0.05 s: the lattice's relaxation, not the split, grows it).
  Simulation& sim = *s.simulation;
  const FluidBody& fluid = sim.fluid();
  const auto energies = [&](double& kinetic) {
    const FluidParticles& f = fluid.particles;
    double internal = 0.0;
    kinetic = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      kinetic += 0.5 * f.mass[i] * f.vel[i].squaredNorm();
      internal += f.mass[i] * fluid.material.eos.internal_energy(f.rho[i]);
    }
    return kinetic + internal;
  };
  const double before = energies(initial_kinetic);
  for (int k = 0; k < steps; ++k) s.schedule->advance(sim, 1.0);
  double kinetic = 0.0;
  return energies(kinetic) - before;
}

}  // namespace

TEST_CASE("Under pressure, the undamped fluid conserves energy only with its pair geometry refreshed", "[fluid]") {
  // reports/pressure.md section 9: the pair geometry cached at the list build, used at the positions
  // of later acoustic steps, adds a force K dx (K the pressure part of the pair stiffness, dx the
  // displacement since the build) that feeds the particle motion. 50 advection steps are 0.04 s.
  double initial_kinetic = 0.0;
  const double refreshed = energy_change_under_pressure(true, 50, initial_kinetic);
  // The semi-discrete equations conserve kinetic plus internal energy. Measured: -1.8 % of the initial
  // kinetic energy after 50 steps, of which -1.25 % is there after the first step (the energy is read
  // with the density the continuity equation carried, set back to the summation at the next step);
  // 5 % leaves room for that offset and position Verlet's error, and the square lattice's relaxation
  // moves tens of per cent of the kinetic energy between the two forms meanwhile.
  CHECK(std::abs(refreshed) < 0.05 * initial_kinetic);
  // The cached geometry (the paper's) gains energy: 19.5 times the initial kinetic energy after 50
  // steps, 3600 times after 100. The bound shows that this test catches it.
  const double cached = energy_change_under_pressure(false, 50, initial_kinetic);
  CHECK(cached > initial_kinetic);
}

TEST_CASE("The Riemann continuity term keeps a column at its hydrostatic state with the hydrostatic balance", "[fluid]") {
  // A water column at rest on a floor between two walls, its density set to the hydrostatic state
  // p = rho0 g (H - y) (linear equation of state). The continuity term (p_i - p_j) / Z is zero pair
  // by pair only for p_i = p_j; summed over a full, symmetric support it cancels for a linear p, but
  // at the free surface the support is cut, and the term raises the density there by about
  // rho g / c (reports/pressure.md section 12). With the hydrostatic balance it acts on
  // p - rho0 g . r, which is constant in this state.
  // The paper's term; the balance with the paper's wall clip (the default); the balance continued
  // into the walls (FluidOptions::rest_state_at_walls, wall_rules.hpp).
  const std::string balance = GENERATE("false", "true", "true, walls");
  const bool walls = balance == "true, walls";
  LoadedScene s = scene_from(R"json({
    "parameters": {"dp": 0.01, "H": 0.2, "g": 9.81},
    "domain": {"lower": [-0.05, -0.05], "upper": [0.35, 0.35]},
    "fluid": {"dp": "dp", "region": {"rectangle": {"lower": [0, 0], "upper": [0.3, "H"]}}, "density": 1000,
              "sound_speed": "10 * sqrt(2 * g * H)", "density_reinitialisation": "free_surface",
              "riemann": {"continuity": true, "momentum": true, "hydrostatic_balance": )json" + std::string(
                             balance == "false" ? "false" : "true") + R"json(},
              "rest_state_at_walls": )json" + (walls ? "true" : "false") + R"json(},
    "walls": [{"name": "tank", "dp": "dp", "region": {"difference": {
                "base": {"rectangle": {"lower": ["-4*dp", "-4*dp"], "upper": ["0.3+4*dp", 0.3]}},
                "subtract": [{"rectangle": {"lower": [0, 0], "upper": [0.3, 0.4]}}]}}}],
    "body_force": {"constant": [0, "-g"]},
    "end_time": 1})json");
  FluidBody& fluid = s.simulation->fluid();
  FluidParticles& f = fluid.particles;
  const Real rho0 = 1000.0, g = 9.81, c = 10.0 * std::sqrt(2.0 * g * 0.2);
  for (std::size_t i = 0; i < f.size(); ++i) {
    f.rho[i] = rho0 + rho0 * g * (0.2 - f.pos[i].y()) / (c * c);
    f.p[i] = fluid.material.eos.pressure(f.rho[i]);
    f.vol[i] = f.mass[i] / f.rho[i];
  }
  compute_pressure_interaction(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), Vec2(0.0, -g));
  // The rate a cut support gives: rho g / c times the support's first moment (2 / pi for half a disc).
  const Real cut_rate = rho0 * g / c * 2.0 / M_PI;
  Real surface = 0.0, floor = 0.0, side = 0.0, bulk = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Vec2 r = f.pos[i];
    const Real rate = std::abs(f.drho_dt[i]) / cut_rate;
    const bool by_side_wall = r.x() < 0.03 || r.x() > 0.27, by_surface = r.y() > 0.2 - 0.03;
    if (by_side_wall && by_surface) continue;  // the corners: both effects at once
    if (by_side_wall) side = std::max(side, rate);
    else if (by_surface) surface = std::max(surface, rate);
    else if (r.y() < 0.03) floor = std::max(floor, rate);
    else bulk = std::max(bulk, rate);
  }
  INFO("hydrostatic_balance " << balance << ": |drho/dt| / (rho g / c 2 / pi), surface " << surface << ", floor "
                              << floor << ", side walls " << side << ", bulk " << bulk);
  if (walls) {
    // p - rho0 g . r is the same at every particle: zero pair by pair. The wall rule continues the
    // same rest state into the dummies (wall_rules.hpp): zero at the floor and the side walls too.
    CHECK(bulk < 1e-9);
    CHECK(surface < 1e-9);
    CHECK(floor < 1e-9);
    CHECK(side < 1e-9);
  } else if (balance == "true") {
    CHECK(bulk < 1e-9);
    CHECK(surface < 1e-9);
    // At a wall pair the dummy's pressure is extrapolated with rho_i instead of rho0:
    // (rho_i - rho0) g (y_i - y_a), of order rho g H / (rho0 c^2) = 0.5 % of the cut rate.
    CHECK(floor < 0.01);
    // Beside a side wall the paper's clip max(0, .) of the whole acceleration gives the dummies above
    // particle i its own pressure instead of the extrapolated one: 0.24 of the cut rate.
    CHECK(side > 0.1);
    CHECK(side < 0.3);
  } else {
    CHECK(surface > 0.5);  // the paper's term on a cut support: 0.9 of the half disc's estimate
    CHECK(bulk < 0.005);   // a full support cancels a linear p, to the volumes' 0.5 % variation
    CHECK(floor < 0.01);  // the floor's dummies complete the support with the extrapolated pressure
    CHECK(side > 0.1);    // the paper's clip beside a side wall, as above
    CHECK(side < 0.3);
  }
}

TEST_CASE("The wall rule continues the rest state's pressure into a dummy particle, and not below the atmosphere", "[fluid]") {
  // wall_rules.hpp: p^d = p_i + rho_i max(0, (a_i - b - abar) . r_ai) + max(G . r_ai, min(-p_i, 0)).
  const Real rho0 = 1000.0, g = 9.81, dy = 0.01, rho_i = 1001.0;
  const Vec2 G(0.0, -rho0 * g), above(0.0, dy), below(0.0, -dy), beside_above(dy, 0.5 * dy);
  const Vec2 at_rest = Vec2::Zero(), still_wall = Vec2::Zero();
  const Real p = 10.0 * rho0 * g * dy;  // ten spacings under the surface
  // A column at rest: the hydrostatic continuation, up and down (the paper's clip kept p_i above).
  CHECK(wall_pressure(p, rho_i, at_rest, still_wall, above, G) == Approx(p - rho0 * g * dy).epsilon(1e-14));
  CHECK(wall_pressure(p, rho_i, at_rest, still_wall, below, G) == Approx(p + rho0 * g * dy).epsilon(1e-14));
  CHECK(wall_pressure(p, rho_i, at_rest, still_wall, beside_above, G) == Approx(p - 0.5 * rho0 * g * dy).epsilon(1e-14));
  // Half a spacing under the surface, the continuation one spacing up stops at the atmosphere's 0.
  const Real shallow = 0.5 * rho0 * g * dy;
  CHECK(wall_pressure(shallow, rho_i, at_rest, still_wall, above, G) == 0.0);
  // A particle already below 0 keeps its own pressure above it (the paper's clip).
  CHECK(wall_pressure(-5.0, rho_i, at_rest, still_wall, above, G) == -5.0);
  // The acceleration beyond the rest state stays clipped: a fluid accelerating away from the wall
  // (or a wall accelerating away) leaves the dummy at the continuation, one accelerating towards it adds.
  const Vec2 up(0.0, 3.0);
  CHECK(wall_pressure(p, rho_i, up, still_wall, below, G) == Approx(p + rho0 * g * dy).epsilon(1e-14));
  CHECK(wall_pressure(p, rho_i, Vec2(-up), still_wall, below, G) == Approx(p + rho0 * g * dy + rho_i * 3.0 * dy).epsilon(1e-14));
  // Without a rest state (G = 0: no body force along an axis that is not periodic, or no balance)
  // the rule is the paper's, to the bit.
  const Vec2 none = Vec2::Zero(), a(0.3, -2.0), abar(0.1, 0.4);
  for (const Vec2& r : {above, below, beside_above})
    CHECK(wall_pressure(p, rho_i, a, abar, r, none) == p + rho_i * std::max(Real(0), (a - abar).dot(r)));
}

TEST_CASE("The measured pressure moment is the lattice's on a lattice and follows the arrangement", "[fluid]") {
  // density_summation.hpp: the mean of m_i = -1/2 sum_j V_j r_ij dW_ij over the particles with a full
  // support. On the square lattice it must be kernel/lattice_moments.hpp's M1 (0.974 at h = 1.3 dp),
  // computed there independently as a lattice sum.
  LoadedScene s = scene_from(periodic_box(R"(, "pressure_lattice_correction": true, "measured_pressure_moment": true)"));
  FluidBody& fluid = s.simulation->fluid();
  reinitialise_density(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), 1.0);
  CHECK(fluid.gradient_moment == Approx(fluid.lattice_gradient).epsilon(1e-12));
  CHECK(fluid.lattice_gradient == Approx(0.974).margin(0.001));
  // Another arrangement, another moment: every other row shifted by 0.3 dp, the same number density.
  for (auto& x : fluid.particles.pos)
    if (std::lround(x.y() / 0.05 - 0.5) % 2 == 1) x.x() += 0.3 * 0.05;
  s.simulation->rebuild_fluid_relations();
  reinitialise_density(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), 1.0);
  CHECK(std::abs(fluid.gradient_moment - fluid.lattice_gradient) > 1e-4);
  // Without the option the pressure force keeps the lattice's M1.
  LoadedScene plain = scene_from(periodic_box(R"(, "pressure_lattice_correction": true)"));
  FluidBody& p = plain.simulation->fluid();
  for (auto& x : p.particles.pos) x.x() += 0.01 * std::sin(7.0 * x.y());  // another arrangement
  reinitialise_density(p, plain.simulation->fluid_inner(), plain.simulation->fluid_contacts(), 1.0);
  CHECK(p.gradient_moment == p.lattice_gradient);
}

TEST_CASE("The viscous force and the shift in one sweep give the bits of the two sweeps", "[fluid]") {
  // A disordered fluid sheared over a floor: every part of both interactions runs (inner pairs, the
  // viscous term's after-inner scaling, the wall pairs with their per-pair forces, the shift).
  const std::string scene = walled_channel_with(R"(, "transport_velocity_alpha": 0.25)");
  LoadedScene apart = scene_from(scene), together = scene_from(scene);
  for (LoadedScene* s : {&apart, &together}) {
    FluidParticles& f = s->simulation->fluid().particles;
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> jitter(-0.01, 0.01);
    for (std::size_t i = 0; i < f.size(); ++i) {
      f.pos[i] += Vec2(jitter(gen), jitter(gen));
      f.vel[i] = Vec2(f.pos[i].y(), 0.1 * std::sin(6.0 * f.pos[i].x()));
    }
    s->simulation->rebuild_fluid_relations();
  }
  Simulation& a = *apart.simulation;
  Simulation& b = *together.simulation;
  const Vec2Array before = b.fluid().particles.pos;
  compute_viscous_force(a.fluid(), a.fluid_inner(), a.fluid_contacts(), Vec2::Zero());
  correct_transport_velocity(a.fluid(), a.fluid_inner(), a.fluid_contacts());
  compute_viscous_force_and_transport_shift(b.fluid(), b.fluid_inner(), b.fluid_contacts(), Vec2::Zero());
  const FluidParticles& fa = a.fluid().particles;
  const FluidParticles& fb = b.fluid().particles;
  double largest_force = 0.0, largest_shift = 0.0;  // both terms ran
  for (std::size_t i = 0; i < fa.size(); ++i) {
    REQUIRE(fa.force_prior[i] == fb.force_prior[i]);
    REQUIRE(fa.pos[i] == fb.pos[i]);
    largest_force = std::max(largest_force, fb.force_prior[i].norm());
    largest_shift = std::max(largest_shift, (fb.pos[i] - before[i]).norm());
  }
  for (std::size_t c = 0; c < a.fluid_contacts().size(); ++c)
    REQUIRE(a.fluid_contacts()[c].pair_viscous_force == b.fluid_contacts()[c].pair_viscous_force);
  CHECK(largest_force > 0.0);
  CHECK(largest_shift > 0.0);
}

TEST_CASE("The continuity pass with its geometry refreshed reads the pairs where the particles are now", "[fluid]") {
  // refresh_divergence_geometry: after the particles moved since the list build, the velocity divergence
  // (and its wall term) is the one a list built at the new positions gives, to the kernel's tail; the
  // cached pass differs at first order in the move (reports/pressure.md section 38). A channel with walls,
  // a jittered lattice and a sheared flow; each particle moves by up to 1e-3 dp.
  const auto drho_dt = [](bool refresh, bool rebuild_after_move) {
    LoadedScene s = scene_from(walled_channel_with(fmt::format(R"(, "refresh_divergence_geometry": {})", refresh)));
    Simulation& sim = *s.simulation;
    FluidParticles& f = sim.fluid().particles;
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> jitter(-0.005, 0.005), move(-5e-5, 5e-5);
    for (std::size_t i = 0; i < f.size(); ++i) {
      f.pos[i] += Vec2(jitter(gen), jitter(gen));
      f.vel[i] = Vec2(f.pos[i].y() * f.pos[i].y(), 0.2 * std::sin(6.0 * f.pos[i].x()));
    }
    sim.rebuild_fluid_relations();
    for (Vec2& x : f.pos) x += Vec2(move(gen), move(gen));
    if (rebuild_after_move) sim.rebuild_fluid_relations();
    std::fill(f.drho_dt.begin(), f.drho_dt.end(), 0.0);
    add_velocity_divergence_and_dissipation(sim.fluid(), sim.fluid_inner(), sim.fluid_contacts());
    return f.drho_dt;
  };
  const RealArray refreshed = drho_dt(true, false), rebuilt = drho_dt(false, true), cached = drho_dt(false, false);
  double scale = 0.0, refreshed_error = 0.0, cached_error = 0.0;
  for (std::size_t i = 0; i < rebuilt.size(); ++i) {
    scale = std::max(scale, std::abs(rebuilt[i]));
    refreshed_error = std::max(refreshed_error, std::abs(refreshed[i] - rebuilt[i]));
    cached_error = std::max(cached_error, std::abs(cached[i] - rebuilt[i]));
  }
  REQUIRE(scale > 0.1);
  // A pair within 1e-4 h of the support's edge changes dW by (1e-4)^2 of its size (Wendland C2's
  // derivative vanishes there quadratically): far below 1e-8 of the largest rate.
  CHECK(refreshed_error <= 1e-8 * scale);
  CHECK(cached_error > 1e-5 * scale);  // the cached pass is off by the move's first order
}

TEST_CASE("The transport-velocity shift per unit time does not depend on an advection CFL below the paper's", "[fluid]") {
  // The same disordered box shifted once at CFL 0.25, 0.0625 and 0.5 (the advection step is CFL h / U):
  // a quarter of the displacement in a quarter of the step, and the paper's displacement above 0.25
  // (reports/pressure.md section 35).
  const auto shifted = [](double cfl) {
    LoadedScene s = scene_from(periodic_box(fmt::format(R"(, "transport_velocity_alpha": 0.25, "advection_cfl": {})", cfl)));
    FluidParticles& f = s.simulation->fluid().particles;
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> jitter(-0.01, 0.01);
    for (Vec2& x : f.pos) x += Vec2(jitter(gen), jitter(gen));
    s.simulation->rebuild_fluid_relations();
    const Vec2Array before = f.pos;
    correct_transport_velocity(s.simulation->fluid(), s.simulation->fluid_inner(), s.simulation->fluid_contacts());
    Vec2Array shift(f.size());
    for (std::size_t i = 0; i < f.size(); ++i) shift[i] = f.pos[i] - before[i];
    return shift;
  };
  const Vec2Array paper = shifted(0.25), small = shifted(0.0625), large = shifted(0.5);
  double largest = 0.0;
  for (std::size_t i = 0; i < paper.size(); ++i) {
    REQUIRE((small[i] - 0.25 * paper[i]).norm() <= 1e-15);  // positions near 1: round-off of the difference
    REQUIRE(large[i] == paper[i]);
    largest = std::max(largest, paper[i].norm());
  }
  CHECK(largest > 1e-4);  // the jitter of 0.2 dp is shifted by more than round-off
}

TEST_CASE("Next to a wall the continuity equation carries the density as the summation moves it; the mirror twice as fast", "[fluid]") {
  // wall_rules.hpp: a fluid moving as a whole towards a wall changes its summation density only through
  // the wall's kernel sums. The summation's rule makes the continuity equation's wall term the time
  // derivative of those sums, so that the next re-initialisation finds the density where the equation
  // carried it; the paper's mirror doubles it. The derivative is a central difference of the summation
  // over two copies of the lattice moved by -+ eps along the motion (the same particle order).
  const Real eps = 1e-5;
  const Vec2 v(0.0, -1.0);  // towards the bottom wall
  auto scene = [&](const std::string& rule, Real offset) {
    return scene_from(R"({
      "parameters": {"dp": 0.05, "y0": )" + fmt::format("{:.17g}", offset) + R"(},
      "domain": {"lower": [0, -0.3], "upper": [1, 1.3], "periodic": [true, false]},
      "fluid": {"dp": "dp", "region": {"rectangle": {"lower": [0, "y0"], "upper": [1, "0.5 + y0"]}}, "density": 1,
                "sound_speed": 10, "wall_continuity": ")" + rule + R"("},
      "walls": [{"name": "bottom", "dp": "dp", "region": {"rectangle": {"lower": [0, -0.2], "upper": [1, 0]}}}],
      "end_time": 1})");
  };
  auto summation = [&](Real offset) {
    LoadedScene s = scene("summation", offset);
    FluidBody& fluid = s.simulation->fluid();
    reinitialise_density(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), 1.0);
    return fluid.particles.rho;
  };
  const RealArray after = summation(eps * v.y());    // the lattice moved by +eps v
  const RealArray before = summation(-eps * v.y());  // by -eps v
  for (const std::string rule : {"summation", "mirrored"}) {
    LoadedScene s = scene(rule, 0.0);
    FluidBody& fluid = s.simulation->fluid();
    FluidParticles& f = fluid.particles;
    reinitialise_density(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), 1.0);
    for (std::size_t i = 0; i < f.size(); ++i) {
      f.vel[i] = v;
      f.drho_dt[i] = 0.0;
    }
    add_velocity_divergence_and_dissipation(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts());
    // The summation divides by the lattice's kernel sum n0 V0 (1 on the lattice); the continuity
    // equation multiplies by rho_i (rho0 there): their rates differ by that factor exactly.
    const Real lattice_sum = fluid.lattice_number_density * f.mass[0] / fluid.material.rho0();
    const Real factor = (rule == "mirrored" ? 2.0 : 1.0) * lattice_sum;
    int near_wall = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      const Real derivative = (after[i] - before[i]) / (2.0 * eps);
      if (f.pos[i].y() + 0.5 * fluid.dp >= 2.0 * fluid.h()) {  // the wall's first row (y = -dp/2) out of reach
        CHECK(std::abs(f.drho_dt[i]) < 1e-9);
        CHECK(std::abs(derivative) < 1e-6);
        continue;
      }
      ++near_wall;
      // Central differences err by O(eps^2) relative: 1e-6 leaves room for round-off over eps.
      CHECK(f.drho_dt[i] == Approx(factor * derivative).epsilon(1e-6));
      CHECK(derivative > 0.0);  // approaching the wall compresses
    }
    CHECK(near_wall > 0);
  }
}

TEST_CASE("The kernel-gradient corrected pressure force is exact for a linear pressure on a stretched lattice and keeps momentum", "[fluid]") {
  // FluidOptions::pressure_gradient_correction: -V_i V_j ((p_i - p_ref) B_i + (p_j - p_ref) B_j) grad W_ij.
  // On a lattice stretched to 0.9 dp along x every interior particle's support is point-symmetric, so
  // the uniform part cancels, and with B_i = B_j the linear part is B_i A_i a = a exactly. The plain
  // sum returns the lattice moment along each axis, which differ on the stretched lattice.
  const Vec2 gradient(3.0, -2.0);
  auto interior_errors = [&](bool corrected) {
    LoadedScene s = scene_from(periodic_box(fmt::format(R"(, "pressure_gradient_correction": {})", corrected)));
    FluidBody& fluid = s.simulation->fluid();
    FluidParticles& f = fluid.particles;
    for (auto& x : f.pos) x.x() *= 0.9;
    s.simulation->rebuild_fluid_relations();
    reinitialise_density(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), 1.0);
    for (std::size_t i = 0; i < f.size(); ++i) f.p[i] = 7.0 + gradient.dot(f.pos[i]);
    compute_pressure_interaction(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), Vec2::Zero());
    // |f^p / V + grad p| per axis over the particles whose neighbours' supports are full: two
    // supports (4 h = 0.26) from the seams, where the stretched lattice leaves a gap.
    Vec2 largest = Vec2::Zero();
    for (std::size_t i = 0; i < f.size(); ++i) {
      const Vec2& x = f.pos[i];
      if (x.x() < 0.3 || x.x() > 0.6 || x.y() < 0.3 || x.y() > 0.7) continue;
      largest = largest.cwiseMax((f.pressure_force[i] / f.vol[i] + gradient).cwiseAbs());
    }
    return largest;
  };
  const Vec2 corrected = interior_errors(true), plain = interior_errors(false);
  CHECK(corrected.norm() < 1e-9 * gradient.norm());
  CHECK(plain.x() > 1e-3 * std::abs(gradient.x()));  // the plain sum: A_i a, the stretched lattice's moments
  CHECK(plain.y() > 1e-2 * std::abs(gradient.y()));
  // Momentum: antisymmetric pairs sum to zero on any arrangement and any pressure.
  LoadedScene s = scene_from(periodic_box(R"(, "pressure_gradient_correction": true)"));
  FluidBody& fluid = s.simulation->fluid();
  FluidParticles& f = fluid.particles;
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> offset(-0.2 * 0.05, 0.2 * 0.05), pressure(-3.0, 10.0);
  for (auto& x : f.pos) x += Vec2(offset(gen), offset(gen));
  s.simulation->rebuild_fluid_relations();
  reinitialise_density(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), 1.0);
  for (auto& p : f.p) p = pressure(gen);
  compute_pressure_interaction(fluid, s.simulation->fluid_inner(), s.simulation->fluid_contacts(), Vec2::Zero());
  Vec2 total = Vec2::Zero();
  double scale = 0.0;
  for (const Vec2& force : f.pressure_force) {
    total += force;
    scale += force.norm();
  }
  CHECK(total.norm() < 1e-13 * scale);
}

namespace {

// A confined fluid in a walled box [0, 1]^2 (not periodic) around a disk wall at (0.5, 0.5), with the
// linear pressure reference, and its pressure set to p(x) = level + gradient . x through the density.
struct LinearPressureBox {
  LoadedScene scene;
  LinearPressureBox(const std::string& reference, bool periodic_x = false, Real background_pressure = 0.0)
      : scene(scene_from(fmt::format(R"({{
    "parameters": {{"dp": 0.05}},
    "domain": {{"lower": [-0.3, -0.3], "upper": [1.3, 1.3], "periodic": [{}, false]}},
    "fluid": {{"dp": "dp", "density": 1, "sound_speed": 10, "pressure_reference": "{}", "background_pressure": {},
              "region": {{"difference": {{"base": {{"rectangle": {{"lower": [0, 0], "upper": [1, 1]}}}},
                                          "subtract": [{{"circle": {{"center": [0.5, 0.5], "radius": 0.15}}}}]}}}}}},
    "walls": [
      {{"name": "bottom", "dp": "dp", "region": {{"rectangle": {{"lower": [-0.2, -0.2], "upper": [1.2, 0]}}}}}},
      {{"name": "top", "dp": "dp", "region": {{"rectangle": {{"lower": [-0.2, 1], "upper": [1.2, 1.2]}}}}}},
      {{"name": "disk", "dp": "dp", "region": {{"circle": {{"center": [0.5, 0.5], "radius": 0.15}}}},
       "fill": {{"pattern": "rings", "center": [0.5, 0.5], "radius": 0.15}}}}
    ],
    "end_time": 0.1}})", periodic_x, reference, background_pressure))) {}
  FluidBody& fluid() { return scene.simulation->fluid(); }
  // Jiggles the particles (seeded), re-initialises the density, then sets rho so that eos(rho) = p.
  void set_pressure(const std::function<Real(const Vec2&)>& p) {
    FluidParticles& f = fluid().particles;
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> offset(-0.15 * 0.05, 0.15 * 0.05);
    for (auto& x : f.pos) x += Vec2(offset(gen), offset(gen));
    scene.simulation->rebuild_fluid_relations();
    reinitialise_density(fluid(), scene.simulation->fluid_inner(), scene.simulation->fluid_contacts(), 1.0);
    for (std::size_t i = 0; i < f.size(); ++i) {
      f.rho[i] = fluid().material.eos.density(p(f.pos[i]));
      f.vol[i] = f.mass[i] / f.rho[i];
      f.p[i] = fluid().material.eos.pressure(f.rho[i]);
    }
    update_reference_pressure(fluid());
  }
};

}  // namespace

TEST_CASE("The linear pressure reference fits a linear pressure, along the axes that are not periodic", "[fluid]") {
  const Vec2 gradient(3.0, -2.0);
  const auto linear = [&](const Vec2& x) { return 7.0 + gradient.dot(x); };
  LinearPressureBox box("linear");
  box.set_pressure(linear);
  const ReferencePressure& r = box.fluid().reference;
  // Exact up to the density's round-off (p through rho = 1 + p / c^2: about 1e-14 of p).
  CHECK((r.gradient - gradient).norm() < 1e-9 * gradient.norm());
  CHECK(r.at(Vec2(0.3, 0.8)) == Approx(linear(Vec2(0.3, 0.8))).epsilon(1e-10));
  // Periodic along x: a linear field would jump at the seam, so only the y gradient is fitted; the
  // x-dependence then enters the y fit through the jiggled arrangement's slight x-y correlation
  // (measured 6e-5 of the gradient).
  LinearPressureBox periodic("linear", true);
  periodic.set_pressure(linear);
  CHECK(periodic.fluid().reference.gradient.x() == 0.0);
  CHECK(periodic.fluid().reference.gradient.y() == Approx(gradient.y()).epsilon(1e-3));
  // The mean reference is the mean, no gradient.
  LinearPressureBox mean("mean");
  mean.set_pressure(linear);
  CHECK(mean.fluid().reference.gradient == Vec2::Zero());
}

TEST_CASE("With the linear reference a linear pressure pushes with its exact gradient on a disordered arrangement, whatever its level", "[fluid]") {
  // The pair forces see p - p_ref = 0 between fluid particles: a particle whose support holds fluid
  // only feels -V_i grad p exactly. A wall's dummy takes p_i (the wall rule, at rest and without body
  // force), not the linear field, so next to walls and on the disk the pairs keep their share of the
  // field's change across the wall; but p - p_ref is the same whatever the level, so every force (the
  // disk's, with its share -V_a grad p_ref, included) is the same at level 0 and 100 rho U^2 to
  // round-off. The plain sum carries the jiggled arrangement's zero-order residue times the level.
  // The level is the equation of state's background pressure: the same densities and volumes.
  const Vec2 gradient(3.0, -2.0);
  struct Forces {
    Real largest_interior_error = 0.0;  // max |f^p / V + grad p| / |grad p| without boundary pairs
    Vec2Array fluid;
    Vec2 disk = Vec2::Zero();
  };
  auto forces = [&](const std::string& reference, Real level) {
    LinearPressureBox box(reference, false, level);
    box.set_pressure([&](const Vec2& x) { return level + gradient.dot(x); });
    FluidBody& fluid = box.fluid();
    auto& contacts = box.scene.simulation->fluid_contacts();
    compute_pressure_interaction(fluid, box.scene.simulation->fluid_inner(), contacts, Vec2::Zero());
    const FluidParticles& f = fluid.particles;
    std::vector<char> touches_boundary(f.size(), 0);
    Forces out;
    for (const FluidContact& c : contacts) {
      for (std::size_t i = 0; i < f.size(); ++i)
        if (!c.pairs.of(i).empty()) touches_boundary[i] = 1;
      if (c.boundary_name == "disk") {
        out.disk = total_force_on_boundary(c);
        CHECK((c.reference_gradient != nullptr) == (reference == "linear"));  // immersed
      } else {
        CHECK(c.reference_gradient == nullptr);  // the channel's walls bound the fluid
      }
    }
    out.fluid = f.pressure_force;
    for (std::size_t i = 0; i < f.size(); ++i)
      if (!touches_boundary[i])
        out.largest_interior_error = std::max(out.largest_interior_error, (f.pressure_force[i] / f.vol[i] + gradient).norm() / gradient.norm());
    return out;
  };
  const auto largest_change = [](const Forces& a, const Forces& b) {
    Real change = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < a.fluid.size(); ++i) {
      change = std::max(change, (a.fluid[i] - b.fluid[i]).norm());
      scale = std::max(scale, a.fluid[i].norm());
    }
    return change / scale;
  };
  const Forces linear0 = forces("linear", 0.0), linear100 = forces("linear", 100.0);
  CHECK(linear0.largest_interior_error < 1e-9);
  CHECK(largest_change(linear0, linear100) < 1e-9);  // round-off of p through rho at level 100
  CHECK((linear0.disk - linear100.disk).norm() < 1e-9 * linear0.disk.norm());
  const Forces zero0 = forces("zero", 0.0), zero100 = forces("zero", 100.0);
  CHECK(zero0.largest_interior_error > 1e-2);  // the residue times the linear field's own values
  CHECK(largest_change(zero0, zero100) > 1e-1);
}
