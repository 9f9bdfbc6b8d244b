// Transport-velocity correction as a position shift, once per advection step (Adami et al. 2013,
// in the form of the paper's code, METHOD.md section 2):
//   r_i <- r_i - 2 alpha h^2 [ sum_j V_j dW_ij e_ij + sum_a V_a dW_ia e_ia ]
// It moves particles away from crowded regions and keeps the distribution uniform in internal
// flows. It does not change velocities, so momentum is unaffected.
#pragma once

#include "fluid/fluid_body.hpp"

namespace mrsph {

void correct_transport_velocity(FluidBody& fluid, const NeighborList& inner, const std::vector<FluidContact>& contacts);

}  // namespace mrsph
