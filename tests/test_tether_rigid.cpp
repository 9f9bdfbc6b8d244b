// The tethered fish's two mechanical parts against rigid-body mechanics, no fluid: the cable that
// pulls only when taut (Tether) and the region that moves as one rigid body (RigidRegion), both in
// solid/solid_body.hpp.
#include "scene_fixture.hpp"
#include "solid/solid_dynamics.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace mrsph;

namespace {

// A 0.4 x 0.2 block (dp = 0.02: 20 x 10 particles, rho = 1000, M = 80 kg), all of it rigid, with
// one cable from `anchor` to the particles within `attach_radius` of `attach`, rest length L0,
// stiffness k and no cable damping. No gravity.
LoadedScene tethered_block(const std::string& anchor, const std::string& attach, double attach_radius, double rest_length,
                           double stiffness) {
  return scene_from(R"({
    "domain": {"lower": [-5, -5], "upper": [5, 5]},
    "solids": [{"name": "block", "dp": 0.02, "h_over_dp": 1.15,
                "region": {"rectangle": {"lower": [-0.2, -0.1], "upper": [0.2, 0.1]}},
                "material": {"model": "neo_hookean", "density": 1000, "youngs_modulus": 1e6, "poisson_ratio": 0.3},
                "rigid": {"rectangle": {"lower": [-1, -1], "upper": [1, 1]}},
                "tethers": [{"anchor": )" + anchor + R"(, "rest_length": )" + std::to_string(rest_length) +
                    R"(, "stiffness": )" + std::to_string(stiffness) + R"(, "damping": 0,
                             "attach": {"circle": {"center": )" + attach + R"(, "radius": )" +
                    std::to_string(attach_radius) + R"(}}}]}],
    "end_time": 10})");
}

Vec2 mass_centre(const SolidBody& s) {
  Vec2 c = Vec2::Zero();
  double m = 0.0;
  for (std::size_t a = 0; a < s.particles.size(); ++a) {
    c += s.particles.mass[a] * s.particles.pos[a];
    m += s.particles.mass[a];
  }
  return c / m;
}

double total_mass(const SolidBody& s) {
  double m = 0.0;
  for (double x : s.particles.mass) m += x;
  return m;
}

// Rotation of the block: the angle of the vector between two particles that start on the long axis.
double block_angle(const SolidBody& s, std::size_t a, std::size_t b) {
  const Vec2 d = s.particles.pos[b] - s.particles.pos[a];
  return std::atan2(d.y(), d.x());
}

}  // namespace

TEST_CASE("A cable pulls the rigid block back like a spring while taut and lets it fly while slack", "[solid][tether]") {
  // The cable pulls through the mass centre (attached to the whole block), anchor on the x axis at
  // distance L0 + x0: a harmonic quarter period x = x0 cos(w t), w = sqrt(k / M), until the cable
  // is slack at t = pi / (2 w); then no force: constant speed x0 w towards the anchor.
  const double M = 80.0, k = 2000.0, x0 = 0.05, L0 = 1.0;
  LoadedScene s = tethered_block("[1.05, 0]", "[0, 0]", 1.0, L0, k);
  Simulation& sim = *s.simulation;
  const SolidBody& block = sim.solids()[0];
  REQUIRE(std::abs(total_mass(block) - M) < 1e-9 * M);
  const double w = std::sqrt(k / M);  // 5 rad/s
  const double quarter = M_PI / (2.0 * w);

  // Half-way through the taut phase.
  const double t1 = 0.5 * quarter;
  while (sim.time < t1 - 1e-12) s.schedule->advance(sim, std::min(t1 - sim.time, 1e-3));
  const double expected_x1 = -x0 * std::cos(w * t1) + x0;  // the centre moves towards the anchor by x0 (1 - cos)
  INFO("taut: centre x " << mass_centre(block).x() << ", expected " << expected_x1);
  // Position-based Verlet with sub-steps of the solid's own criterion (~5e-4 s here, w dt ~ 0.0025)
  // follows the harmonic motion to far better than 0.1 % of x0.
  CHECK(std::abs(mass_centre(block).x() - expected_x1) < 1e-3 * x0);

  // Well into the slack phase: free flight at the speed the spring gave.
  const double t2 = quarter + 0.2;
  while (sim.time < t2 - 1e-12) s.schedule->advance(sim, std::min(t2 - sim.time, 1e-3));
  const double speed = solid_momentum(block).x() / M;
  const double expected_x2 = x0 + x0 * w * (t2 - quarter);
  INFO("slack: speed " << speed << " (expected " << x0 * w << "), centre x " << mass_centre(block).x() << " (expected " << expected_x2 << ")");
  CHECK(std::abs(speed - x0 * w) < 1e-3 * x0 * w);
  CHECK(std::abs(mass_centre(block).x() - expected_x2) < 1e-3 * x0);
  CHECK(std::abs(mass_centre(block).y()) < 1e-12);
}

TEST_CASE("A rigid region turns under an off-centre pull as a rigid body: a = F / M, alpha = torque / I", "[solid][rigid]") {
  // The cable pulls at the block's right end (the four particles within 0.025 of (0.19, 0), centred
  // at (0.18, 0)) straight up along y, from an anchor 11 above, stretched by x0 = 1: over the first
  // 0.02 s the block lifts by 2.5e-4 and turns by 0.003 rad, so the pull stays F = k x0 along y to
  // within 0.3 %, 0.18 from the centre. Continuous rectangle: I = M (a^2 + b^2) / 12.
  const double M = 80.0, k = 100.0, x0 = 1.0, L0 = 10.0;
  const double arm = 0.18;
  LoadedScene s = tethered_block("[0.18, 11.0]", "[0.19, 0]", 0.025, L0, k);
  Simulation& sim = *s.simulation;
  const SolidBody& block = sim.solids()[0];
  // Two particles on the row just above the long axis, at the ends: their angle is the rotation.
  const auto particle_at = [&](const Vec2& where) {
    std::size_t best = 0;
    for (std::size_t a = 1; a < block.particles.size(); ++a)
      if ((block.particles.pos0[a] - where).norm() < (block.particles.pos0[best] - where).norm()) best = a;
    return best;
  };
  const std::size_t left = particle_at(Vec2(-0.19, 0.01)), right = particle_at(Vec2(0.19, 0.01));
  const double theta0 = block_angle(block, left, right);
  const double end_distance = (block.particles.pos[right] - block.particles.pos[left]).norm();

  const double t1 = 0.02;
  while (sim.time < t1 - 1e-12) s.schedule->advance(sim, std::min(t1 - sim.time, 1e-3));
  const double F = k * x0;
  const double inertia = M * (0.4 * 0.4 + 0.2 * 0.2) / 12.0;
  const double expected_lift = 0.5 * F / M * t1 * t1;
  const double expected_angle = 0.5 * F * arm / inertia * t1 * t1;
  const double angle = block_angle(block, left, right) - theta0;
  INFO("centre y " << mass_centre(block).y() << " (expected " << expected_lift << "), angle " << angle << " (expected "
                   << expected_angle << ")");
  // The particles' own moment of inertia (20 x 10 lattice) is 0.4 % below the continuous one, and
  // the pull changes by under 0.3 %: 2 %.
  CHECK(std::abs(mass_centre(block).y() - expected_lift) < 0.02 * expected_lift);
  CHECK(std::abs(angle - expected_angle) < 0.02 * expected_angle);
  // The region stays rigid: the two end particles keep their distance.
  CHECK(std::abs((block.particles.pos[right] - block.particles.pos[left]).norm() - end_distance) < 1e-6 * end_distance);
}
