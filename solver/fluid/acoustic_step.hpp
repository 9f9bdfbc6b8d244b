// One acoustic step of the fluid with the position-based Verlet scheme (paper Eqs. 36-38; the
// split of the Riemann dissipation follows the paper's code, METHOD.md sections 2, 3 and 6):
//
// First half:  rho^{n+1/2} = rho^n + dt/2 drho/dt;  p = EoS(rho);  r^{n+1/2} = r^n + dt/2 v^n;
//              f^p_i = -V_i sum_j V_j (p_i + p_j) dW_ij e_ij                              (Eq. 28)
//                      -V_i sum_a V_a (p_i + p^d_ia) dW_ia e_ia                          (Eqs. 21, 30)
//              p^d_ia = p_i + rho_i max(0, (a^prior_i - abar_a).(r_a - r_i))          (Adami 2012)
//              drho/dt = rho_i sum_j V_j (p_i - p_j - rho0 g.r_ij)/Z dW_ij
//                        + rho_i sum_a V_a (p_i - p^d_ia - rho0 g.r_ia)/Z dW_ia
//                        (riemann_dissipation.hpp: the rest state's part taken out; the paper has no g here)
//                        (or, with the fluid option delta_sph, the delta-SPH term D_i of density_diffusion.hpp)
//              v^{n+1} = v^n + dt (f^p + f^d + F^prior)/m + dt g(t + dt/2)
// Second half: r^{n+1} = r^{n+1/2} + dt/2 v^{n+1};
//              drho/dt += rho_i sum_j V_j (v_i - v_j).e_ij dW_ij                          (Eq. 27)
//                       + rho_i sum_a V_a (v_i - v^d_a).e_ia dW_ia   (v^d_a: wall_rules.hpp's continuity rule)
//              f^d_i = V_i sum_j V_j Pi(u_ij) dW_ij e_ij + V_i sum_a V_a Pi(u_ia) dW_ia n_f  (if enabled)
//              rho^{n+1} = rho^{n+1/2} + dt/2 drho/dt
// f^d is applied in the next acoustic step, to the fluid and (with the opposite sign) to the
// boundary, so each pair exchanges exactly opposite impulses.
//
// The halves are composed of the operators below, which the velocity-based Verlet schedule
// composes differently.
#pragma once

#include "core/parallel.hpp"
#include "fluid/fluid_body.hpp"

namespace mrsph {

void acoustic_first_half(FluidBody& fluid, const NeighborList& inner, std::vector<FluidContact>& contacts, Real dt,
                         const Vec2& body_acceleration);
// `sharing`: Balanced where the pass runs beside the solids' sub-steps (core/parallel.hpp).
void acoustic_second_half(FluidBody& fluid, const NeighborList& inner, std::vector<FluidContact>& contacts, Real dt,
                          Sharing sharing = Sharing::Static);

// rho += dt_density drho/dt; p = EoS(rho); V = m / rho; r += dt_position v.
void advance_density_and_position(FluidBody& fluid, Real dt_density, Real dt_position);
// r += dt v.
void advance_position(FluidBody& fluid, Real dt);
// f^p (with every boundary pair force stored) and drho/dt = the Riemann pressure-difference term;
// with kick_dt != 0, then the kick below with kick_dt, in the same pass.
void compute_pressure_interaction(FluidBody& fluid, const NeighborList& inner, std::vector<FluidContact>& contacts,
                                  const Vec2& body_acceleration, Real kick_dt = 0.0);
// v += dt ((f^p + f^d + F^prior) / m + g).
void kick(FluidBody& fluid, Real dt, const Vec2& body_acceleration);
// drho/dt += rho div v terms; f^d (and its boundary reactions) from the current velocities. In the
// same pass, where non-zero: r += position_dt v before, rho += density_dt drho/dt after.
void add_velocity_divergence_and_dissipation(FluidBody& fluid, const NeighborList& inner,
                                             std::vector<FluidContact>& contacts, Real position_dt = 0.0,
                                             Real density_dt = 0.0, Sharing sharing = Sharing::Static);

// Sum over the pairs of each boundary particle of -pair_force: the reaction of the fluid on the
// boundary, exactly opposite to what the fluid received (pair by pair).
void accumulate_boundary_reaction(const FluidContact& contact, const Vec2Array& pair_force, Vec2Array& reaction);

}  // namespace mrsph
