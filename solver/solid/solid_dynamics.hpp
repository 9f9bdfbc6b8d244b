// Total Lagrangian SPH for the elastic solid (paper section 2.2; METHOD.md section 4), written with
// the gradient weights w_ab of gradient_weights.hpp (for the paper's B0: w_ab = V_b B_a grad0_a W_ab):
//   Deformation rate:            dF_a/dt = sum_b (v_b - v_a) (x) w_ab
//   Density (Eq. 17):            rho_a = rho0 / det F_a
//   Momentum (Eqs. 19, 25, 29):  f_a = V_a P_a sum_b w_ab - sum_b V_b P_b w_ba
//                                (= V_a sum_b V_b (P_a B_a^T + P_b B_b^T) grad0_a W_ab for B0),
//                                m_a dv_a/dt = f_a + F^prior_a + m_a g
//   Optional damping:            P += F eta dE/dt, dE/dt = sym(F^T dF/dt) (SolidOptions)
#pragma once

#include "solid/solid_body.hpp"
#include "solid/solid_contact.hpp"

#include <span>

#include <functional>

namespace mrsph {

// Builds the reference neighbour list, the gradient weights, the reference normals, and sets
// F = I, rho = rho0.
void initialise_solid(SolidBody& solid);

// Solid time-step criterion (Eq. 34): cfl * s * min_a min( sqrt(h / |a_a|), h / (c + |v_a|) ), with
// s the stiffness scale of the gradient weights (1 for the paper's B0; gradient_weights.hpp).
Real solid_time_step(const SolidBody& solid);

// Advances the solid over [t, t + dt] with position-based Verlet sub-steps (Eqs. 39-41: half step of
// r and F, full step of v, half step of r and F) that respect the criterion and sum to dt exactly
// (kappa = ceil(dt / dt_S), re-evaluated every sub-step). The second half of one sub-step and the
// first half of the next are done in one pass over the particles. Constrained particles keep
// r = r0 and v = 0; their F still evolves. body_acceleration(t) is g at time t (sampled at the
// middle of each sub-step). Returns the number of sub-steps.
long long advance_solid(SolidBody& solid, Real t, Real dt, const std::function<Vec2(Real)>& body_acceleration);

// The same for bodies in contact (solid_contact.hpp): all of them advance together, in sub-steps that
// respect every body's criterion, and the contact forces join the external forces of each sub-step
// (evaluated at its middle, like the internal forces). Returns the sub-steps summed over the bodies.
long long advance_solids(std::span<SolidBody> solids, std::span<SolidContact> contacts, Real t, Real dt,
                         const std::function<Vec2(Real)>& body_acceleration);

// The operators a sub-step is made of, exposed for tests and diagnostics:
// dF/dt of every particle from the current velocities.
void compute_deformation_rate(SolidBody& solid);
// rho = rho0 / J and P of every particle from the current F.
void compute_stress(SolidBody& solid);
// f_a from the stored P (excluding F^prior and body force).
Vec2 internal_force(const SolidBody& solid, std::size_t a);

// One velocity-based Verlet sub-step (kick-drift-kick), for the comparison schedule only:
// v += dt/2 a; r += dt v; F += dt dF/dt(v); a = (f + F^prior)/m + g; v += dt/2 a.
void solid_substep_velocity_verlet(SolidBody& solid, Real dt, const Vec2& body_acceleration);

// Tension of a tether and its direction (zero when slack), for the current state.
Vec2 tether_force(const SolidBody& solid, const Tether& tether);

// Current normals n = R(F) n0, with R the rotation part of F (METHOD.md section 3).
void update_solid_normals(SolidBody& solid);

Real solid_kinetic_energy(const SolidBody& solid);
Real solid_strain_energy(const SolidBody& solid);
Vec2 solid_momentum(const SolidBody& solid);

}  // namespace mrsph
