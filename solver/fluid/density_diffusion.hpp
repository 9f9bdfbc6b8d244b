// delta-SPH density diffusion with Antuono's correction (Antuono, Colagrossi, Marrone & Molteni
// 2010, Comput. Phys. Commun. 181, Eqs. 5-6; the form of Marrone et al. 2011, CMAME 200, Eq. 4):
//   D_i = delta h c0 sum_j V_j psi_ij . grad_i W_ij,
//   psi_ij = 2 (rho_j - rho_i) (r_j - r_i) / |r_j - r_i|^2 - (<grad rho>_i^L + <grad rho>_j^L),
//   <grad rho>_i^L = L_i sum_j V_j (rho_j - rho_i) grad_i W_ij,  L_i = [sum_j V_j (r_j - r_i) (x) grad_i W_ij]^-1.
// With grad_i W_ij = dW_ij e_ij and r_j - r_i = -r_ij e_ij, the pair term is
//   delta h c0 V_j [2 (rho_i - rho_j) / r_ij - (<grad rho>_i + <grad rho>_j) . e_ij] dW_ij:
// zero for a density linear in space (a hydrostatic column, a uniform pressure gradient), where the
// Riemann term (p_i - p_j) / (rho0 c) of the paper's continuity equation diffuses the hydrostatic
// profile away (reports/pressure.md section 4). Fluid pairs only, as in the papers: the walls'
// density is not integrated. A particle whose matrix is near singular (a few neighbours at a free
// surface) gets no correction, the plain term of Molteni & Colagrossi (2009).
#pragma once

#include "fluid/fluid_body.hpp"

namespace mrsph {

// <grad rho>_i^L for every fluid particle, into fluid.density_gradient (nothing when delta = 0).
void compute_renormalised_density_gradient(FluidBody& fluid, const NeighborList& inner);

// The pair term above divided by delta h c0: D_i = delta h c0 sum over the inner pairs.
inline Real density_diffusion_pair(Real rho_i, Real rho_j, const Vec2& gradient_i, const Vec2& gradient_j,
                                   Real vol_j, const Neighbor& n) {
  return vol_j * (2.0 * (rho_i - rho_j) / n.r - (gradient_i + gradient_j).dot(n.e)) * n.dW;
}

}  // namespace mrsph
