// Total Lagrangian SPH for the elastic solid (paper section 2.2; METHOD.md section 4).
//   Correction matrix (Eq. 16):  B_a = ( sum_b V_b (r0_b - r0_a) (x) grad0_a W_ab )^-1
//   Deformation rate:            dF_a/dt = [ sum_b V_b (v_b - v_a) (x) grad0_a W_ab ] B_a
//   Density (Eq. 17):            rho_a = rho0 / det F_a
//   Momentum (Eqs. 19, 25):      f_a = V_a sum_b V_b (P_a B_a^T + P_b B_b^T) grad0_a W_ab,
//                                m_a dv_a/dt = f_a + F^prior_a + m_a g
// with grad0_a W_ab = dW/dr(r0_ab) e0_ab evaluated once in the reference configuration.
#pragma once

#include "solid/solid_body.hpp"

namespace mrsph {

// Builds the reference neighbour list, B, the reference normals, and sets F = I, rho = rho0.
void initialise_solid(SolidBody& solid);

// Solid time-step criterion (Eq. 34): cfl * min_a min( sqrt(h / |a_a|), h / (c + |v_a|) ).
Real solid_time_step(const SolidBody& solid);

// One position-based Verlet sub-step (Eqs. 39-41): half step of r and F, full step of v, half
// step of r and F. Constrained particles keep r = r0 and v = 0; their F still evolves.
void solid_substep(SolidBody& solid, Real dt, const Vec2& body_acceleration);

// The operators a sub-step is made of, exposed for tests and diagnostics:
// dF/dt of every particle from the current velocities.
void compute_deformation_rate(SolidBody& solid);
// rho = rho0 / J and P B^T of every particle from the current F.
void compute_stress(SolidBody& solid);
// f_a from the stored P B^T (excluding F^prior and body force).
Vec2 internal_force(const SolidBody& solid, std::size_t a);

// Current normals n = R(F) n0, with R the rotation part of F (METHOD.md section 3).
void update_solid_normals(SolidBody& solid);

Real solid_kinetic_energy(const SolidBody& solid);
Real solid_strain_energy(const SolidBody& solid);
Vec2 solid_momentum(const SolidBody& solid);

}  // namespace mrsph
