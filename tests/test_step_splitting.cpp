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
