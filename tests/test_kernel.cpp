#include "kernel/lattice_moments.hpp"
#include "kernel/wendland_c2.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace mrsph;

namespace {
// Radial quadrature of f(r) 2 pi r over [0, 2h] (Simpson, fine enough for 1e-10).
template <class F>
double radial_integral(const WendlandC2& k, F f) {
  const int n = 20000;
  const double a = 0.0, b = k.cutoff(), dr = (b - a) / n;
  double s = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double r = a + i * dr;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    s += w * f(r) * 2.0 * kPi * r;
  }
  return s * dr / 3.0;
}
}  // namespace

TEST_CASE("Wendland C2 is normalised in 2D for any h", "[kernel]") {
  for (double h : {0.013, 1.0, 7.5}) {
    const WendlandC2 k(h);
    CHECK(radial_integral(k, [&](double r) { return k.W(r); }) == Approx(1.0).epsilon(1e-9));
  }
}

TEST_CASE("Wendland C2's first and second derivatives match finite differences", "[kernel]") {
  const WendlandC2 k(0.37);
  const auto W = [&](double r) { return k.W(r); };
  const auto dW = [&](double r) { return k.dW(r); };
  // q = 0.5, where d2W changes sign (1 - 2q), is away from the samples.
  for (double q : {0.05, 0.3, 0.9, 1.4, 1.99}) {
    const double r = q * k.h(), e = 1e-6 * k.h();
    const auto centred = [&](auto f) { return (f(r + e) - f(r - e)) / (2 * e); };
    CHECK(k.dW(r) == Approx(centred(W)).epsilon(1e-6));
    CHECK(k.d2W(r) == Approx(centred(dW)).epsilon(1e-6));
    CHECK(k.dW(r) < 0.0);
  }
  CHECK(k.d2W(0.25 * k.h()) < 0.0);  // concave at its peak
  CHECK(k.d2W(k.h()) > 0.0);
  CHECK(k.W(k.cutoff()) == 0.0);
  CHECK(k.dW(k.cutoff()) == 0.0);
  CHECK(k.d2W(k.cutoff()) == 0.0);
  CHECK(k.W(0.0) == Approx(7.0 / (4.0 * kPi * 0.37 * 0.37)));
}

TEST_CASE("The continuum gradient moment is -2, so SPH gradients and Laplacians are consistent", "[kernel]") {
  // integral of r W'(r) d^2r = -2: the identity behind the pressure-gradient and Morris operators.
  const WendlandC2 k(0.5);
  CHECK(radial_integral(k, [&](double r) { return r * k.dW(r); }) == Approx(-2.0).epsilon(1e-9));
}

TEST_CASE("Lattice sums at h = 1.3 dp match the values the method relies on", "[kernel]") {
  const double dp = 0.02;
  const WendlandC2 k(1.3 * dp);
  // METHOD.md section 1: sigma0 dp^2 = 1.0105 for h = 1.3 dp.
  CHECK(lattice_number_density(k, dp) * dp * dp == Approx(1.0105).epsilon(1e-4));
  // The lattice Laplacian moment approaches its continuum value 1 as h/dp grows, and is a few
  // percent low at h = 1.3 dp: the bias the viscous lattice correction removes.
  const double m13 = lattice_laplacian_moment(k, dp, 0.0);
  CHECK(m13 == Approx(0.9739).epsilon(1e-3));
  const WendlandC2 wide(3.0 * dp);
  CHECK(lattice_laplacian_moment(wide, dp, 0.0) == Approx(1.0).epsilon(2e-3));
}
