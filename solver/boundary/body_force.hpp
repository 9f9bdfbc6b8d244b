// A body force per unit mass that may vary in time:
//   g(t) = constant + amplitude cos(omega t + phase)
// Gravity is `constant`; the Womersley channel is driven by amplitude = (A / rho, 0).
#pragma once

#include "core/types.hpp"

#include <cmath>

namespace mrsph {

struct BodyForce {
  Vec2 constant = Vec2::Zero();
  Vec2 amplitude = Vec2::Zero();
  Real angular_frequency = 0.0;
  Real phase = 0.0;

  Vec2 at(Real t) const {
    if (amplitude.isZero()) return constant;
    return constant + amplitude * std::cos(angular_frequency * t + phase);
  }
};

}  // namespace mrsph
