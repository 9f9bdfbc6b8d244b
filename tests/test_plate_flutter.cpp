// The linear flutter theory used as the fish's reference (verification/theory/plate_flutter.hpp),
// checked piece by piece against closed-form answers.
#include "theory/exponential_integral.hpp"
#include "theory/plate_flutter.hpp"

#include <catch2/catch.hpp>
#include <gsl/gsl_sf_bessel.h>

#include <cmath>

using namespace mrsph::verification::theory;

namespace {

// Theodorsen's function C(k) = H1(k) / (H1(k) + i H0(k)), H_n = J_n - i Y_n (Hankel, second kind).
Complex theodorsen(double k) {
  const Complex h1(gsl_sf_bessel_J1(k), -gsl_sf_bessel_Y1(k)), h0(gsl_sf_bessel_J0(k), -gsl_sf_bessel_Y0(k));
  return h1 / (h1 + Complex(0.0, 1.0) * h0);
}

}  // namespace

TEST_CASE("exponential integral E1 matches tabulated values on both sides of the series/fraction switch") {
  // Abramowitz & Stegun table 5.1 (E1(1), E1(2)); E1(i) = -Ci(1) + i (Si(1) - pi/2), A&S 5.1.23, table 5.2.
  CHECK(std::abs(exponential_integral_e1(1.0) - 0.21938393439552027) < 1e-13);
  CHECK(std::abs(exponential_integral_e1(2.0 - 1e-9) - 0.04890051070806112) < 1e-10);
  CHECK(std::abs(exponential_integral_e1(2.0 + 1e-9) - 0.04890051070806112) < 1e-10);
  const Complex e1_i = exponential_integral_e1(Complex(0.0, 1.0));
  CHECK(std::abs(e1_i - Complex(-0.33740392290096813, 0.94608307036718301 - M_PI / 2)) < 1e-13);
  // Across each switch between representations the values agree: |z| = 2 off the axis, the 45-degree
  // line about the negative real axis (series / continued fraction), |z| = 40 (series / asymptotic).
  auto continuous = [](Complex a, Complex b) {
    const Complex ea = exponential_integral_e1(a), eb = exponential_integral_e1(b);
    INFO(a << ": " << ea << ", " << b << ": " << eb);
    CHECK(std::abs(ea - eb) < 1e-7 * std::abs(ea));
  };
  continuous(std::polar(2.0 - 1e-9, 2.0), std::polar(2.0 + 1e-9, 2.0));
  continuous(std::polar(7.0, 0.75 * M_PI - 1e-9), std::polar(7.0, 0.75 * M_PI + 1e-9));
  continuous(std::polar(30.0, 0.75 * M_PI - 1e-9), std::polar(30.0, 0.75 * M_PI + 1e-9));
  continuous(std::polar(40.0 - 1e-10, 0.9 * M_PI), std::polar(40.0 + 1e-10, 0.9 * M_PI));
  // On the cut from above: E1(-x + i0) = -Ei(x) - i pi, Ei(5) = 40.185275355803177 (A&S table 5.1).
  CHECK(std::abs(exponential_integral_e1(Complex(-5.0, 0.0)) - Complex(-40.185275355803177, -M_PI)) < 1e-11 * 40.2);
}

TEST_CASE("the vortex lattice gives Theodorsen's lift on a heaving flat plate") {
  // Plate of half-chord b in a stream U, heaving upwards as h e^{i omega t}: the lift is
  // L = -pi rho b^2 h'' - 2 pi rho U b C(k) h' (Theodorsen 1935), k = omega b / U: the added mass and
  // the circulatory lift through the wake. With 200 cosine-spaced panels the lattice is within 0.19 %
  // of it (measured; the error halves with the number of panels); 0.5 % is the check.
  const double b = 0.5, U = 1.3, rho = 1.1;
  const VortexLattice lattice(-b, b, 200, U, rho);
  const Eigen::VectorXcd w = Eigen::VectorXcd::Ones(lattice.panels()), slope = Eigen::VectorXcd::Zero(lattice.panels());
  for (double k : {0.05, 0.2, 0.5, 1.0, 3.0}) {
    const double omega = k * U / b;
    const Complex lambda(0.0, omega);
    const Eigen::VectorXcd gamma = lattice.circulation(lambda, w, slope);
    const Complex lift = lattice.steady_force(gamma).sum() + lattice.unsteady_force(lambda, gamma).sum();
    const Complex expected = M_PI * rho * b * b * omega * omega - 2.0 * M_PI * rho * U * b * theodorsen(k) * lambda;
    INFO("k = " << k << ": lattice " << lift << ", Theodorsen " << expected);
    CHECK(std::abs(lift - expected) < 5e-3 * std::abs(expected));
  }
  // Theodorsen's function itself, against its classical table (C(0.5) = 0.5979 - 0.1507 i).
  CHECK(std::abs(theodorsen(0.5) - Complex(0.5979, -0.1507)) < 1e-4);
}

TEST_CASE("the beam model's first frequencies are those of a uniform cantilever") {
  // Clamped-free uniform beam, no fluid: omega_n = (beta_n L)^2 sqrt(D / (m L^4)), beta_1 L = 1.8751,
  // beta_2 L = 4.6941; plane strain D = E h^3 / (12 (1 - nu^2)).
  SlenderBody body;
  body.thickness = [](double) { return 0.1; };
  body.x_begin = 0.0;
  body.x_end = 2.0;
  body.solid_density = 3.0;
  body.youngs_modulus = 500.0;
  body.poisson_ratio = 0.3;
  body.support = NoseSupport::Clamped;
  FlowModel flow;
  flow.elements = 40;
  const FlutterModes modes = flutter_modes(body, flow, 0.0);
  REQUIRE(modes.in_vacuo.empty());  // max_frequency 0 keeps nothing: the frequency filter works
  const FlutterModes all = flutter_modes(body, flow, 0.5);  // the first two modes lie at 0.055 and 0.34
  REQUIRE(all.in_vacuo.size() >= 2);
  const double D = 500.0 * 1e-3 / (12.0 * (1 - 0.09)), m = 0.3, L = 2.0;
  const double scale = std::sqrt(D / (m * std::pow(L, 4)));
  CHECK(all.in_vacuo[0].imag() == Approx(1.8751040687 * 1.8751040687 * scale).epsilon(1e-6));
  CHECK(all.in_vacuo[1].imag() == Approx(4.6940911330 * 4.6940911330 * scale).epsilon(1e-6));
  CHECK(std::abs(all.in_vacuo[0].real()) < 1e-6 * all.in_vacuo[0].imag());  // no damping without fluid (round-off of the eigensolver)
}

TEST_CASE("a flexible plate in a stream is stable when stiff, flutters when soft, and the threshold is found") {
  // Clamped-free uniform plate, the fluid as heavy as the solid, length 1, thickness 0.05 (a light
  // flag: mass ratio rho_S h / (rho_F L) = 0.05). Stiff: every mode decays (the wake carries energy
  // away); soft: flutter. The threshold must lie between and reproduce itself as a root.
  SlenderBody body;
  body.thickness = [](double) { return 0.05; };
  body.x_begin = 0.0;
  body.x_end = 1.0;
  body.support = NoseSupport::Clamped;
  FlowModel flow;
  flow.panels = 120;
  flow.elements = 20;
  body.youngs_modulus = 1e5;
  CHECK(flutter_modes(body, flow, 5.0).largest_growth(5.0) < 0.0);
  body.youngs_modulus = 1.0;
  CHECK(flutter_modes(body, flow, 5.0).largest_growth(5.0) > 0.0);
  const auto critical = critical_youngs_modulus(body, flow, 5.0, 1.0, 1e5);
  REQUIRE(critical.has_value());
  body.youngs_modulus = *critical * 1.05;
  CHECK(flutter_modes(body, flow, 5.0).largest_growth(5.0) < 0.0);
  body.youngs_modulus = *critical / 1.05;
  CHECK(flutter_modes(body, flow, 5.0).largest_growth(5.0) > 0.0);
}
