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

// The relaxation of one advection step's re-initialisation: density_relaxation times
// FluidOptions::paper_step_fraction(). The paper's reset replaces the density once per step, at its
// CFL of 0.25. Each reset is a small pressure kick where the summation and the carried density
// differ; at a quarter of the step four resets per unit time gave a pressure-driven channel five
// times the particles' noise (transverse velocity 0.0057 against 0.0012 U) and 1.2 % less flow, and
// raised the Taylor-Green vortex's viscosity as the step shrank. Scaled, both are independent of
// the step (reports/pressure.md section 41). At CFL 0.25 and above it is density_relaxation.
Real density_relaxation_per_step(const FluidOptions& options);

// The smallest rho_sum / rho0 over the fluid: 1 where every particle's kernel support is filled by
// fluid, walls or solids; 0.79 for the top row of a lattice under a free surface, 0.74-0.84 next to
// a lattice cut by a slanted or curved wall (h = 1.3 dp): voids that the initial relaxation fills.
Real smallest_support_fraction(const FluidBody& fluid, const NeighborList& inner,
                               const std::vector<FluidContact>& contacts);

}  // namespace mrsph
