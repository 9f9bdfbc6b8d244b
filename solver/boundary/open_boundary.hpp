// Open boundaries: an inlet or outlet through which fluid enters and leaves the domain
// (reports/open-boundaries.md; choices and peers in reports/METHOD-CHOICES.md).
//
// A boundary is a plane x_a = plane (a = axis) with a buffer of width W outside the domain: a
// particle's depth d = side (x_a - plane) is > 0 in the buffer, <= 0 in the domain. Buffer
// particles are ordinary neighbours of the domain's particles (so those near the plane see a full
// kernel support), but their state is imposed, not integrated:
//   velocity condition  v = v_b(x, t) (an inflow profile); p extrapolated from the domain
//   pressure condition  p = p_b(t), or weakly reflecting (reflection_time tau > 0):
//                         p = p_b(t) + rho0 c (u_n - ubar_n),   dubar_n/dt = (u_n - ubar_n) / tau
//                       (the incoming characteristic p - rho0 c u_n held at its mean: a wave leaving
//                       the domain is not sent back, the mean pressure is still p_b); the normal
//                       velocity u_n extrapolated, no tangential velocity (the flow crosses the
//                       plane normally: buffer particles, which feel no wall, cannot drift into one).
//                       Optionally p_b is a total pressure where the fluid enters (u_n < 0, inflow
//                       or backflow): p = p_b - rho0 u_n^2 / 2, Bernoulli's static pressure of fluid
//                       drawn from rest at p_b. It bounds the energy a backflow brings in: with the
//                       static p_b a bin's inflow meets no resistance, and at the valve's outlet a
//                       streak of particles along one bin ran away to Mach 1 when the valve closed
//   both                rho = EOS^-1(p), vol = m / rho
// Extrapolation from the domain's particles within one kernel support of the plane (the band), in
// bins of width dp along the plane (a channel's profile u(y) is kept): the velocity with zero normal
// gradient (the bin's mean, or optionally for a pressure condition the normal velocity's least-squares
// polynomial of degree 4 along the plane, which holds a parabolic profile exactly but not a streak one
// bin wide: with 2-3 particles per bin, the bin means let a single bin's inflow feed itself); the pressure continued linearly, with the slope of a least-squares line
// of p against depth over the band (through (0, p_b) for the pressure condition), since a constant
// buffer pressure would put a kink at the plane that the kernel smears half a support outwards.
//
// Exchange, once per advection step (particles move < dp / 2 in one; works both ways):
//   a buffer particle now in the domain   joins the domain
//   a domain particle now in the buffer   joins the buffer
//   a particle deeper than W              is deleted
//   then, in each bin where the buffer moves towards the plane, new particles fill the space
//   opened at the far end, at the normal spacing dx = m / (rho_b dp) at which the density
//   summation sees the buffer's density rho_b
// Mass balance: the ledger counts the mass crossing the plane into the domain, so the domain's mass
// changes by exactly the sum of the ledgers.
#pragma once

#include "boundary/inflow.hpp"
#include "fluid/fluid_body.hpp"

#include <functional>
#include <string>
#include <vector>

namespace mrsph {

enum class OpenBoundaryCondition { Velocity, Pressure };

struct OpenBoundaryLedger {
  Real mass_into_domain = 0.0;  // mass that crossed the plane into the domain, minus mass out
  long long created = 0;        // buffer particles made at the far end
  long long deleted = 0;        // particles removed beyond the buffer's far end
};

struct OpenBoundary {
  std::string name;
  int axis = 0;        // the plane's normal axis
  Real plane = 0.0;    // coordinate of the plane along axis
  int side = 1;        // +1: the buffer lies above the plane along axis (outward normal +axis), -1 below
  Real width = 0.0;    // W, at least one kernel support
  Real span_lower = 0.0, span_upper = 0.0;  // the buffer's extent along the plane
  OpenBoundaryCondition condition = OpenBoundaryCondition::Pressure;
  InflowProfile velocity;              // velocity condition
  std::function<Real(Real)> pressure;  // pressure condition: p_b(t)
  Real reflection_time = 0.0;          // tau of the weakly reflecting pressure condition; 0: p = p_b
  bool total_pressure_inflow = false;  // p_b is the total pressure of entering fluid (above)
  bool smooth_normal_velocity = false; // pressure condition: u_n along the plane fitted by a
                                       // polynomial of degree 4 instead of each bin's mean (below)
  OpenBoundaryLedger ledger;
  RealArray mean_normal_velocity;      // ubar_n per bin (weakly reflecting state; empty until first use)

  Real depth(const Vec2& p) const { return side * (p[axis] - plane); }
  bool in_buffer(const Vec2& p) const { const Real d = depth(p); return d > 0.0 && d <= width; }
  // Outward unit normal.
  Vec2 normal() const { Vec2 n = Vec2::Zero(); n[axis] = side; return n; }
};

// Sets each particle's zone from its position (at set-up).
void classify_fluid_zones(FluidParticles& fluid, const std::vector<OpenBoundary>& boundaries);

// The exchange above; particles keep their order, new ones are appended, in a fixed order.
void exchange_buffer_particles(FluidBody& fluid, std::vector<OpenBoundary>& boundaries);

// Imposes the buffer particles' state at time t; dt > 0 advances the weakly reflecting mean
// (0: after a density re-initialisation, within the same instant).
void impose_buffer_states(FluidBody& fluid, std::vector<OpenBoundary>& boundaries, Real t, Real dt);

// Mass of the particles in the domain (not in a buffer).
Real domain_mass(const FluidParticles& fluid);

}  // namespace mrsph
