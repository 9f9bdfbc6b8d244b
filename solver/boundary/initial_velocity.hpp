// Initial velocity fields a scene can prescribe.
//   uniform:          v = value
//   womersley:        v = (u(y, t0), 0), the plane-channel Womersley profile (womersley_profile.hpp)
//   cantilever_mode:  the first bending mode of a clamped-free beam along x (Gray, Monaghan &
//                     Swift 2001; CASES.md), x measured from the clamp at x_clamp:
//                     v_y = V [M (cos kx - cosh kx) - N (sin kx - sinh kx)] / Q, k L = 1.875,
//                     M = sin kL + sinh kL, N = cos kL + cosh kL, Q = 2 (cos kL sinh kL - sin kL cosh kL)
//                     (zero on the clamped side, x < x_clamp)
//   field:            v = (u(x, y), v(x, y)), any field given as a function of position (the scene
//                     reader builds it from expressions over x, y and the scene's parameters)
#pragma once

#include "boundary/womersley_profile.hpp"
#include "core/types.hpp"

#include <functional>
#include <variant>

namespace mrsph {

struct UniformVelocity {
  Vec2 value = Vec2::Zero();
};

struct WomersleyVelocity {
  WomersleyProfile profile;
  Real time = 0.0;
};

struct CantileverModeVelocity {
  Real clamp_x = 0.0;
  Real length = 1.0;
  Real amplitude = 1.0;  // V = V_f c0
  Real kL = 1.875;
};

struct VelocityField {
  std::function<Vec2(const Vec2&)> at;
};

using InitialVelocity = std::variant<UniformVelocity, WomersleyVelocity, CantileverModeVelocity, VelocityField>;

Vec2 initial_velocity_at(const InitialVelocity& field, const Vec2& p);

}  // namespace mrsph
