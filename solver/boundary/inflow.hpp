// Inflow buffer (METHOD.md section 7): in a periodic channel, the fluid particles inside the
// buffer region have their velocity reset to a prescribed profile u(y, t) after every acoustic
// step; density and pressure are left alone.
//   Womersley (pulsatile; the plane-channel solution of womersley_profile.hpp, CASES.md section 3):
//     u_x = u_W(y, t), u_y = 0
//   expression: u(x, y, t) and v(x, y, t) written in the scene (a pulse, a measured waveform)
//   parabolic channel (Turek & Hron 2006, with the factor 4 the paper drops, CASES.md section 1):
//     u_x = 1.5 Ubar(t) 4 (y - y0)(H - (y - y0)) / H^2,
//     Ubar(t) = U0 (1 - cos(pi t / t_ramp)) / 2 for t < t_ramp, else U0;  u_y = 0.
// Channel drive (`drive_channel`, on by default): while the parabolic profile ramps, the whole
// fluid is given the body acceleration dUbar/dt along x, the pressure gradient -rho dUbar/dt that
// accelerates an incompressible channel's fluid as one. Without it only the buffer is set moving:
// its upstream face, the periodic seam, withdraws like a piston from the fluid at rest behind it,
// and the seam cavitated (density -51 %, Mach 2.0 in FSI2's ramp over 2; reports/stability.md).
// The solids do not get the drive's Froude-Krylov share (rho_f / rho_s) dUbar/dt: it acts along
// the channel, on the bodies here an axial load of 0.08 per unit mass at most, during the ramp.
#pragma once

#include "boundary/womersley_profile.hpp"
#include "geometry/shapes.hpp"
#include "neighbor/domain_box.hpp"
#include "particles/fluid_particles.hpp"

#include <functional>
#include <memory>
#include <variant>

namespace mrsph {

struct ParabolicInflowProfile {
  Real channel_bottom = 0.0;  // y0
  Real channel_height = 1.0;  // H
  Real mean_velocity = 1.0;   // U0
  Real ramp_time = 0.0;       // t_ramp; 0: no ramp

  Real ramp(Real t) const;
  Real ramp_rate(Real t) const;  // d ramp / dt
  Vec2 velocity(const Vec2& p, Real t) const;
};

struct WomersleyInflowProfile {
  WomersleyProfile profile;
  Vec2 velocity(const Vec2& p, Real t) const { return Vec2(profile.velocity(p.y(), t), 0.0); }
};

struct ExpressionInflowProfile {
  std::function<Vec2(const Vec2&, Real)> field;  // (position, time) -> velocity
  Vec2 velocity(const Vec2& p, Real t) const { return field(p, t); }
};

using InflowProfile = std::variant<ParabolicInflowProfile, WomersleyInflowProfile, ExpressionInflowProfile>;
Vec2 inflow_velocity(const InflowProfile& profile, const Vec2& p, Real t);

struct InflowBuffer {
  ShapePtr region;
  InflowProfile profile;
  bool drive_channel = true;

  // The channel drive above (zero after the ramp, without one, and for the other profiles).
  Vec2 channel_acceleration(Real t) const;

  // Positions are tested in their periodic image inside the box.
  void apply(FluidParticles& fluid, Real t, const DomainBox& box) const;
};

}  // namespace mrsph
