#include "boundary/womersley_profile.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace mrsph;

namespace {

WomersleyProfile profile_for(double wo) {
  WomersleyProfile w;
  w.channel_height = 2.0;  // h = H/2 = 1
  w.pressure_gradient_amplitude = 3.0;
  w.density = 1.5;
  w.angular_frequency = 2.0;
  w.kinematic_viscosity = w.angular_frequency / (wo * wo);  // Wo = h sqrt(omega / nu)
  return w;
}

// CASES.md, Appendix A with the erratum: the real form, written independently of the complex one.
double real_form(const WomersleyProfile& w, double y, double t) {
  const double h = 0.5 * w.channel_height, yc = y - w.channel_bottom - h, wo = w.womersley_number();
  const double phi1 = wo / std::sqrt(2.0) * (1.0 + yc / h), phi2 = wo / std::sqrt(2.0) * (1.0 - yc / h);
  const double gamma = std::cosh(std::sqrt(2.0) * wo) + std::cos(std::sqrt(2.0) * wo);
  const double A = w.pressure_gradient_amplitude, wt = w.angular_frequency * t;
  return A / (w.density * w.angular_frequency * gamma) *
         ((std::sinh(phi1) * std::sin(phi2) + std::sinh(phi2) * std::sin(phi1)) * std::cos(wt) +
          (gamma - std::cosh(phi1) * std::cos(phi2) - std::cosh(phi2) * std::cos(phi1)) * std::sin(wt));
}

}  // namespace

TEST_CASE("Womersley centre-line amplitude and lag match the check values of CASES.md", "[womersley]") {
  struct Check { double wo, amplitude, lag_deg; };
  for (const Check& c : {Check{1.0, 0.4632, 22.7}, Check{5.0, 1.0540, 91.2}, Check{10.0, 0.9988, 89.9}}) {
    const WomersleyProfile w = profile_for(c.wo);
    const double unit = w.pressure_gradient_amplitude / (w.density * w.angular_frequency);
    const Vec2 U = w.complex_amplitude(1.0);  // centre line
    CHECK(U.norm() / unit == Approx(c.amplitude).margin(5e-5));
    // u = |U| cos(omega t - lag) with the driving -dp/dx = A cos(omega t): lag = -arg U.
    CHECK(-std::atan2(U.y(), U.x()) * 180.0 / kPi == Approx(c.lag_deg).margin(0.05));
  }
}

TEST_CASE("Womersley profile: no slip at the walls, off-centre peak at Wo = 5 and 10", "[womersley]") {
  for (double wo : {1.0, 5.0, 10.0}) {
    const WomersleyProfile w = profile_for(wo);
    for (double t : {0.0, 0.3, 1.1}) {
      CHECK(std::abs(w.velocity(0.0, t)) < 1e-12);
      CHECK(std::abs(w.velocity(2.0, t)) < 1e-12);
    }
  }
  for (double wo : {5.0, 10.0}) {
    const WomersleyProfile w = profile_for(wo);
    const double unit = w.pressure_gradient_amplitude / (w.density * w.angular_frequency);
    double peak = 0.0;
    for (int k = 0; k <= 2000; ++k) peak = std::max(peak, w.complex_amplitude(2.0 * k / 2000.0).norm());
    CHECK(peak / unit == Approx(1.069).margin(0.002));
  }
}

TEST_CASE("The complex form equals the corrected real form of the paper's Appendix A", "[womersley]") {
  for (double wo : {0.5, 1.0, 5.0, 10.0, 20.0}) {
    const WomersleyProfile w = profile_for(wo);
    for (double y : {0.05, 0.4, 1.0, 1.7})
      for (double t : {0.0, 0.37, 2.9}) CHECK(w.velocity(y, t) == Approx(real_form(w, y, t)).margin(1e-10));
  }
}
