#include "boundary/inflow.hpp"
#include "run/runner.hpp"
#include "scene_fixture.hpp"

#include <catch2/catch.hpp>

using namespace mrsph;

TEST_CASE("The parabolic inflow's ramp rate is the derivative of its ramp", "[inflow]") {
  ParabolicInflowProfile p;
  p.ramp_time = 2.0;
  // Trapezoidal integral of the rate against the ramp; the rule's error is (T^3 / 12 n^2) max|f''|.
  const int n = 2000;
  Real integral = 0.0, worst = 0.0;
  for (int k = 0; k < n; ++k) {
    const Real t0 = 2.5 * k / n, t1 = 2.5 * (k + 1) / n;
    integral += 0.5 * (t1 - t0) * (p.ramp_rate(t0) + p.ramp_rate(t1));
    worst = std::max(worst, std::abs(integral - p.ramp(t1)));
  }
  CHECK(worst < 1e-6);
  CHECK(p.ramp_rate(2.0) == 0.0);
  CHECK(p.ramp_rate(-0.1) == 0.0);
  p.ramp_time = 0.0;  // no ramp: the full velocity from the start, no drive
  CHECK(p.ramp_rate(0.5) == 0.0);
}

TEST_CASE("A periodic channel started by its inflow ramp accelerates as one with the channel drive", "[inflow]") {
  // An empty channel 3 x 1, periodic along x, a 0.5-long buffer, Re = 100, c = 10 U0, the
  // profile ramped over 0.5 (a fast start: the acoustic transit of the channel is 0.3), run to the
  // ramp's end. With the buffer alone its upstream face withdraws from the fluid at rest like a
  // piston: a rarefaction of about Ubar / c in density, 10 % at Ubar = U0, more as the periodic
  // echoes add up. With the drive the fluid accelerates with the buffer; what is left is the
  // buffer's parabola against the drive's uniform acceleration, a viscous adjustment.
  const bool drive = GENERATE(true, false);
  LoadedScene s = scene_from(R"json({
    "parameters": {"dp": 0.05, "H": 1.0, "L": 3.0, "wall": 0.2},
    "domain": {"lower": [0, "-wall - dp"], "upper": ["L", "H + wall + dp"], "periodic": [true, false]},
    "fluid": {"dp": "dp", "region": {"rectangle": {"lower": [0, 0], "upper": ["L", "H"]}}, "density": 1,
              "sound_speed": 10, "viscosity": 0.01, "reference_velocity": 1},
    "walls": [{"name": "bottom", "dp": "dp", "region": {"rectangle": {"lower": [0, "-wall"], "upper": ["L", 0]}}},
              {"name": "top", "dp": "dp", "region": {"rectangle": {"lower": [0, "H"], "upper": ["L", "H + wall"]}}}],
    "inflow": {"buffer": {"rectangle": {"lower": [0, 0], "upper": [0.5, "H"]}},
               "profile": {"type": "parabolic_channel", "bottom": 0, "height": "H", "mean_velocity": 1, "ramp_time": 0.5},
               "drive_channel": )json" + std::string(drive ? "true" : "false") + R"json(},
    "end_time": 0.5})json");
  RunOptions options;
  options.end_time = 0.5;
  const RunResult r = run_simulation(*s.simulation, *s.schedule, s.observers, options);
  REQUIRE(r.completed);
  const FluidParticles& f = s.simulation->fluid().particles;
  Real mean_u = 0.0;
  for (const Vec2& v : f.vel) mean_u += v.x() / static_cast<Real>(f.size());
  INFO("drive " << drive << ": largest density deviation " << r.compressibility.density_deviation.value
                << " at t = " << r.compressibility.density_deviation.time << " ("
                << r.compressibility.density_deviation.position.transpose() << "), Mach " << r.compressibility.mach.value
                << ", mean u at the ramp's end " << mean_u);
  if (drive) {
    // Weakly compressible through the ramp (measured 0.96 %; Mach^2 = 1 % at c = 10 U0), and the
    // channel's fluid moves with the inflow (measured 0.984; the walls' boundary layers lag).
    CHECK(r.compressibility.density_deviation.value < 0.02);
    CHECK(mean_u == Approx(1.0).epsilon(0.05));
  } else {
    // The piston's rarefaction at the seam (measured 11 %), and a channel half at rest (0.45).
    CHECK(r.compressibility.density_deviation.value > 0.05);
    CHECK(mean_u < 0.7);
  }
}
