// Fluid-structure coupling (paper section 3; METHOD.md section 5).
//  - Forces of the fluid on a boundary body (Eqs. 23-24 with h_F, Eqs. 30-31): each pair force is
//    computed once, on the fluid side, and the boundary particle receives exactly its negative, so
//    momentum is exchanged pair by pair. The pressure part changes every acoustic step, the
//    viscous part once per advection step, the Riemann dissipation part is the one the fluid
//    applies in the same acoustic step. Their sum is the solid's F^prior, held constant over the
//    solid sub-steps of the acoustic step.
//  - Kinematics the fluid sees (Eq. 35): the solid velocity and acceleration averaged over the
//    acoustic step (SolidKinematics below), or, for comparison, the code's second
//    difference or the instantaneous values of the last sub-step.
#pragma once

#include "fluid/fluid_body.hpp"
#include "solid/solid_body.hpp"

namespace mrsph {

// How the fluid sees an elastic solid within an acoustic step (paper Eq. 35 and section 3.2):
//   Averaged                  time averages over the acoustic step [t, t + dt]:
//                             vbar = (r(t + dt) - r(t)) / dt,  abar = (v(t + dt) - v(t)) / dt
//   AveragedSecondDifference  the paper's code: the same vbar, abar = (vbar^{n+1} - vbar^n) / dt,
//                             a second difference of positions over two acoustic steps
//   Instantaneous             velocity and acceleration of the last solid sub-step
enum class SolidKinematics { Averaged, AveragedSecondDifference, Instantaneous };

// F^prior_a = -sum over pairs (pressure + viscous) + dissipation reaction, and an immersed body's
// share -V_a grad p_ref of a linear reference pressure (FluidContact::reference_gradient).
void set_force_from_fluid(const FluidContact& contact, SolidParticles& solid);

// Total force of the fluid on a boundary body in the current acoustic step.
Vec2 total_force_on_boundary(const FluidContact& contact);

// The viscous part of it: the pairs' viscous forces, computed once per advection step.
Vec2 viscous_force_on_boundary(const FluidContact& contact);

// The impulse record of the contacts that keep one (FluidContact::records_impulse): a kick of the
// fluid by dt adds dt times the boundary's share of it; the record's reader clears it.
void clear_boundary_impulses(std::vector<FluidContact>& contacts);
void add_boundary_impulses(std::vector<FluidContact>& contacts, Real dt);
// The force of the fluid on a boundary, and its viscous part, averaged over the time since the
// record was cleared (the current acoustic step's if the contact keeps no record or no step has
// been taken since).
Vec2 mean_force_on_boundary(const FluidContact& contact);
Vec2 mean_viscous_force_on_boundary(const FluidContact& contact);

void begin_kinematics_average(SolidParticles& solid);
void end_kinematics_average(SolidParticles& solid, Real dt, SolidKinematics mode);

}  // namespace mrsph
