// Transport-velocity correction as a position shift, once per advection step (Adami et al. 2013,
// in the form of the paper's code, METHOD.md section 2):
//   r_i <- r_i - 2 alpha h^2 [ sum_j V_j dW_ij e_ij + sum_a V_a dW_ia e_ia ]
// It moves particles away from crowded regions and keeps the distribution uniform in internal
// flows. It does not change velocities, so momentum is unaffected.
// The same shift, repeated before t = 0 with the bodies held still, is the initial particle
// relaxation (Simulation::initialise; fluid option relaxation_steps): a lattice cut by a slanted or
// curved boundary leaves voids between fluid and solid particles, whose density deficit would
// otherwise start the run with spurious pressure jets.
#pragma once

#include "fluid/fluid_body.hpp"

namespace mrsph {

void correct_transport_velocity(FluidBody& fluid, const NeighborList& inner, const std::vector<FluidContact>& contacts);

// The coefficient of the shift above in one advection step: transport_velocity_alpha times
// FluidOptions::paper_step_fraction(), min(1, advection_cfl / 0.25). The paper's shift is a
// displacement per step, calibrated at its advection CFL of 0.25; the step is CFL h / U, so at a
// smaller CFL the same displacement per step would act more often, and the shift per unit time
// would grow as 1 / CFL. Scaled, the shift per unit time is the paper's whatever CFL is chosen
// below 0.25 (a pressure-driven open channel's centre velocity 0.983 / 1.155 at CFL 0.25 / 0.06
// unscaled: the entering lattice is broken up, reports/pressure.md section 35). Above 0.25 the
// paper's displacement per step is kept: a stronger one diverges (alpha = 1 at CFL 0.25, section
// 34). At CFL 0.25 it is alpha, bit for bit.
Real shift_alpha_per_step(const FluidOptions& options);

// The shift above with coefficient alpha, each particle's shift limited to max_shift in length.
void shift_towards_uniform_distribution(FluidBody& fluid, const NeighborList& inner,
                                        const std::vector<FluidContact>& contacts, Real alpha, Real max_shift);

}  // namespace mrsph
