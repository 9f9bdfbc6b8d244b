#include "core/step_splitting.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace mrsph;

TEST_CASE("Sub-steps respect the criterion and add up to the interval", "[time]") {
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(0.01, 1.0);
  for (int trial = 0; trial < 1000; ++trial) {
    const double interval = u(gen), criterion = u(gen) * interval * 0.3;
    double elapsed = 0.0;
    int steps = 0;
    for (bool last = false; !last; ++steps) {
      const SplitStep s = split_remaining(interval - elapsed, criterion);
      REQUIRE(s.size <= criterion * (1 + 1e-12));
      REQUIRE(s.size > 0.0);
      elapsed += s.size;
      last = s.last;
    }
    CHECK(elapsed == Approx(interval).epsilon(1e-14));
    // The paper's kappa = [dt / dt_S] + 1 (here the ceiling): never more.
    CHECK(steps == static_cast<int>(std::ceil(interval / criterion * (1 - 1e-12))));
  }
}

TEST_CASE("Full acoustic steps pass the advection step by less than one step and land on a limit", "[time]") {
  // The paper's Algorithm 1: steps of the criterion (at most Dt each) until their sum reaches Dt.
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(0.01, 1.0);
  for (int trial = 0; trial < 1000; ++trial) {
    const double Dt = u(gen), criterion = u(gen) * Dt * (trial % 10 == 0 ? 3.0 : 0.7);
    const double limit = trial % 3 == 0 ? Dt * (0.5 + u(gen)) : 1e30;  // an output time, or none
    double elapsed = 0.0;
    int steps = 0;
    for (bool last = false; !last; ++steps) {
      const SplitStep s = full_step_towards(elapsed, Dt, limit, criterion);
      REQUIRE(s.size <= std::min(criterion, Dt) * (1 + 1e-12));  // the criterion and Dt, never passed
      REQUIRE(s.size > 0.0);
      elapsed += s.size;
      last = s.last;
    }
    if (limit < elapsed + 1e-12 * Dt) {
      CHECK(elapsed == Approx(limit).epsilon(1e-14));  // cut to land on the limit
    } else {
      const double step = std::min(criterion, Dt);
      CHECK(elapsed >= Dt * (1 - 1e-12));                            // reaches Dt
      CHECK(elapsed < Dt + step);                                      // by less than one step past it
      CHECK(steps == static_cast<int>(std::ceil(Dt / step * (1 - 1e-12))));  // full steps until Dt is reached
    }
  }
}

TEST_CASE("Full acoustic steps inside the advection step never pass it and stop one step short at most", "[time]") {
  // floor(Dt / dt_ac) full steps (one step of Dt where dt_ac > Dt); an advection step that ends on a
  // limit (Dt cut to an output time) is split equally to land on it.
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(0.01, 1.0);
  for (int trial = 0; trial < 1000; ++trial) {
    const double Dt = u(gen), criterion = u(gen) * Dt * (trial % 10 == 0 ? 3.0 : 0.7);
    const double limit = trial % 3 == 0 ? Dt : 1e30;  // Dt cut to an output time, or no limit near
    double elapsed = 0.0;
    int steps = 0;
    for (bool last = false; !last; ++steps) {
      const SplitStep s = full_step_inside(elapsed, Dt, limit, criterion);
      REQUIRE(s.size <= std::min(criterion, Dt) * (1 + 1e-12));
      REQUIRE(s.size > 0.0);
      elapsed += s.size;
      last = s.last;
    }
    CHECK(elapsed <= Dt * (1 + 1e-12));  // never past the advection criterion
    if (limit == Dt) {
      CHECK(elapsed == Approx(limit).epsilon(1e-14));
    } else {
      const double full = std::floor(Dt / criterion * (1 + 1e-12));
      CHECK(steps == std::max(1, static_cast<int>(full)));
      CHECK(elapsed > Dt - criterion);  // one more full step would not have fitted
    }
  }
}
