#include "metrics/convergence.hpp"
#include "metrics/signal_metrics.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace mrsph::verification;

TEST_CASE("Oscillation metrics recover mean, amplitude and frequency of a sine", "[metrics]") {
  std::vector<double> t, y;
  for (int k = 0; k <= 20000; ++k) {
    t.push_back(k * 0.01);
    // settling transient, then 0.8 sin(2 pi 0.19 t) about 2.0
    const double settle = t.back() < 20 ? 0.5 * std::exp(-t.back()) : 0.0;
    y.push_back(2.0 + 0.8 * std::sin(2 * M_PI * 0.19 * t.back()) + settle);
  }
  const auto s = oscillation_stats(t, y, 50.0);
  REQUIRE(s);
  CHECK(s->mean == Approx(2.0).margin(2e-3));
  CHECK(s->amplitude == Approx(0.8).epsilon(1e-4));
  CHECK(s->frequency == Approx(0.19).epsilon(1e-4));
  CHECK(s->cycles >= 25);
  const auto f = spectral_peak_frequency(t, y, 50.0, 0.05, 1.0);
  REQUIRE(f);
  CHECK(*f == Approx(0.19).epsilon(2e-3));
}

TEST_CASE("A moving average removes noise and keeps a slow oscillation", "[metrics]") {
  std::vector<double> t, y;
  for (int k = 0; k <= 10000; ++k) {
    t.push_back(k * 0.01);
    y.push_back(std::sin(2 * M_PI * 0.2 * t.back()) + 0.3 * ((k % 2) ? 1.0 : -1.0));  // alternating noise
  }
  const auto smooth = moving_average(t, y, 0.5);
  // A box filter of width w scales a sinusoid of frequency f by sinc = sin(pi f w) / (pi f w)
  // (0.984 here); the alternating noise averages to 0.3 / 51 over the 51 samples of the window.
  const double sinc = std::sin(M_PI * 0.2 * 0.5) / (M_PI * 0.2 * 0.5);
  for (std::size_t k = 100; k + 100 < t.size(); ++k)
    REQUIRE(smooth[k] == Approx(sinc * std::sin(2 * M_PI * 0.2 * t[k])).margin(0.3 / 51 + 1e-3));
}

TEST_CASE("A band pass keeps a shedding-like sinusoid and removes noise, its harmonic and drift", "[metrics]") {
  // A lift of amplitude 1.09 at St 0.2198 (Turek & Hron's CFD3) with a line at twice the frequency,
  // an acoustic line at 10.3, sample-to-sample noise and a slow drift, sampled unevenly.
  std::vector<double> t, y;
  double s = 0.0;
  for (int k = 0; s < 70.0; ++k) {
    t.push_back(s);
    y.push_back(1.09 * std::sin(2 * M_PI * 0.2198 * s) + 0.8 * std::sin(2 * M_PI * 0.44 * s + 0.3) +
                0.3 * std::sin(2 * M_PI * 10.3 * s) + 2.0 * ((k % 2) ? 1.0 : -1.0) + 0.01 * s);
    s += (k % 3) ? 0.004 : 0.007;
  }
  const auto band = band_pass(t, y, 30.0, 0.1, 0.35);
  REQUIRE(band);
  CHECK(band->t.size() == 4096 - 2 * 614);  // the untapered middle
  const auto cycles = oscillation_stats(band->t, band->y, band->t.front());
  REQUIRE(cycles);
  // 8.8 periods in the window, 6.2 in its middle: within 1 % on average; cycle by cycle the line at
  // 0.44 leaks in (up to 0.03, below) and beats with the sinusoid.
  CHECK(cycles->amplitude == Approx(1.09).epsilon(0.01));
  CHECK(cycles->amplitude_spread < 0.03);
  CHECK(cycles->frequency == Approx(0.2198).epsilon(0.01));
  // A line outside the band alone, 0.09 from its edge (3.6 / span): what leaks through is 4 % of it.
  std::vector<double> harmonic;
  for (double s2 : t) harmonic.push_back(0.8 * std::sin(2 * M_PI * 0.44 * s2 + 0.3));
  const auto leak = band_pass(t, harmonic, 30.0, 0.1, 0.35);
  REQUIRE(leak);
  double largest = 0.0;
  for (double v : leak->y) largest = std::max(largest, std::abs(v));
  CHECK(largest < 0.05 * 0.8);
  // Under one period of the band's lowest frequency: nothing.
  CHECK_FALSE(band_pass(t, y, 65.0, 0.1, 0.35));
}

TEST_CASE("Oscillation metrics refuse a signal with too few cycles", "[metrics]") {
  std::vector<double> t{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, y{0, 1, 0, -1, 0, 1, 0, -1, 0, 1};
  CHECK_FALSE(oscillation_stats(t, y, 8.5));
}

TEST_CASE("The switching period of a two-state signal with spikes and wobble", "[metrics]") {
  // Period 0.6: open (2.0) for 0.2, then closed (-0.3) wobbling with amplitude 0.8 at 25 Hz, with a
  // spike past each state at each switch. The wobble crosses the mean many times per period, so the
  // mean-crossing count sees extra cycles; the switch count must not.
  std::vector<double> t, y;
  for (int k = 0; k <= 2000; ++k) {
    t.push_back(k * 0.001);
    const double phase = std::fmod(t.back(), 0.6);
    double v = phase < 0.2 ? 2.0 + 0.1 * std::sin(2 * M_PI * 60.0 * t.back()) : -0.3 + 0.8 * std::sin(2 * M_PI * 25.0 * t.back());
    if (phase < 0.004) v = 5.0;                     // overshoot as it opens
    if (std::abs(phase - 0.2) < 0.002) v = -4.0;    // and as it closes
    y.push_back(v);
  }
  const auto s = switching_period(t, y, 0.45);
  REQUIRE(s);
  CHECK(s->period == Approx(0.6).epsilon(0.01));
  CHECK(s->switches == 3);
  const auto crossings = oscillation_stats(t, y, 0.45);
  REQUIRE(crossings);
  CHECK(1.0 / crossings->frequency < 0.2);   // the wobble adds mean crossings
  const auto late = switching_period(t, y, 1.5);  // one switch-up only after t = 1.5
  REQUIRE(late);
  CHECK(late->switches == 1);
  CHECK(std::isnan(late->period));
}

TEST_CASE("Curve comparison: RMS and max error at the reference times, and the peaks", "[metrics]") {
  std::vector<double> t_run, y_run;
  for (int k = 0; k <= 400; ++k) { t_run.push_back(k * 0.001); y_run.push_back(std::sin(10 * t_run.back())); }
  const std::vector<double> t_ref{0.05, 0.1, 0.15, 0.2, 0.25};
  std::vector<double> y_ref;
  for (double s : t_ref) y_ref.push_back(std::sin(10 * s) + 0.01);  // a constant offset of 0.01
  const auto c = compare_curves(t_run, y_run, t_ref, y_ref);
  REQUIRE(c);
  CHECK(c->rms_error == Approx(0.01).epsilon(1e-3));
  CHECK(c->max_error == Approx(0.01).epsilon(1e-3));
  CHECK(c->points == 5);
  CHECK(c->peak_time == Approx(M_PI / 20).margin(1e-3));
  CHECK(c->reference_peak_time == Approx(0.15));
}

TEST_CASE("Three-grid convergence recovers order, limit and GCI of a power law", "[metrics]") {
  // f(h) = 0.855 + 0.2 h^2 at h = 4, 2, 1 (ratio 2).
  auto f = [](double h) { return 0.855 + 0.2 * h * h / 16.0; };
  const auto c = three_grid_convergence(f(4), f(2), f(1), 2.0);
  REQUIRE(c);
  CHECK(c->observed_order == Approx(2.0).epsilon(1e-12));
  CHECK(c->extrapolated == Approx(0.855).epsilon(1e-12));
  CHECK(c->monotone);
  CHECK(c->gci == Approx(1.25 * std::abs((f(1) - f(2)) / f(1)) / 3.0).epsilon(1e-12));
  CHECK(order_from_errors(0.04, 0.01, 2.0) == Approx(2.0));
}

TEST_CASE("The least-squares slope of a noisy line, and none from one point", "[metrics]") {
  // ln A of a decaying vortex: -2 nu k^2 t with an offset and an alternating error of 1e-3.
  std::vector<double> t, y;
  for (int k = 1; k <= 8; ++k) { t.push_back(0.125 * k); y.push_back(-0.3948 * t.back() - 0.02 + (k % 2 ? 1e-3 : -1e-3)); }
  CHECK(least_squares_slope(t, y) == Approx(-0.3948).epsilon(1e-2));
  CHECK(std::isnan(least_squares_slope({1.0}, {2.0})));
  CHECK(std::isnan(least_squares_slope({1.0, 1.0}, {2.0, 3.0})));
}
