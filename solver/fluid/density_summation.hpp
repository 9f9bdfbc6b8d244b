// Density re-initialisation by kernel summation, once per advection step (METHOD.md section 2):
//   rho_sum,i = (rho0 / sigma0) [ W(0) + sum_j W_ij V0_j / V0_i + sum_a W_ia V_a / V0_i ],
// with V0 = m / rho0 and sigma0 the lattice number density, so a particle in a full uniform lattice
// gets exactly rho0. Internal flow: rho_target = rho_sum. Free surface: rho_target = max(rho_sum, rho0).
// The density is then rho + relaxation (rho_target - rho): with relaxation 1 (the paper's) the
// summation replaces the continuity equation's density; below 1 it pulls it towards the summation
// by that fraction (FluidOptions::density_relaxation; reports/pressure.md section 11).
// Then the reference pressure of the pair forces (FluidOptions::pressure_reference) is updated
// (reference_pressure.hpp): the mean pressure of the fluid, a linear fit of it, or 0.
#pragma once

#include "fluid/fluid_body.hpp"

namespace mrsph {

void reinitialise_density(FluidBody& fluid, const NeighborList& inner, const std::vector<FluidContact>& contacts,
                          Real relaxation);

// The smallest rho_sum / rho0 over the fluid: 1 where every particle's kernel support is filled by
// fluid, walls or solids; 0.79 for the top row of a lattice under a free surface, 0.74-0.84 next to
// a lattice cut by a slanted or curved wall (h = 1.3 dp): voids that the initial relaxation fills.
Real smallest_support_fraction(const FluidBody& fluid, const NeighborList& inner,
                               const std::vector<FluidContact>& contacts);

}  // namespace mrsph
