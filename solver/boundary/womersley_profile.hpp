// Plane-channel Womersley flow (CASES.md section 3, with the paper's Appendix A erratum): the
// velocity of a channel of height H driven by -dp/dx = A cos(omega t),
//   u(y', t) = Re{ A / (i rho omega) [1 - cosh(k y') / cosh(k H/2)] e^{i omega t} },
//   k = (1 + i) sqrt(omega / (2 nu)),
// with y' measured from the centre line and nu the kinematic viscosity; Wo = (H/2) sqrt(omega/nu).
// Evaluated with GSL's complex functions.
#pragma once

#include "core/types.hpp"

namespace mrsph {

struct WomersleyProfile {
  Real channel_bottom = 0.0;
  Real channel_height = 1.0;
  Real pressure_gradient_amplitude = 1.0;  // A
  Real angular_frequency = 2.0 * kPi;      // omega
  Real density = 1.0;                      // rho
  Real kinematic_viscosity = 1.0;          // nu

  Real womersley_number() const;
  Real velocity(Real y, Real t) const;  // u_x at height y (absolute), time t
  // Complex amplitude U(y) with u = Re{U e^{i omega t}}: returns (Re U, Im U).
  Vec2 complex_amplitude(Real y) const;
};

}  // namespace mrsph
