// Viscous force (paper Eqs. 18 and 22; Morris et al. 1997), once per advection step:
//   f^v_i = 2 mu V_i sum_j V_j (v_i - v_j) / (r_ij + 0.01 h) dW/dr_ij
//         + 2 mu V_i sum_a V_a (1 + d_a / d_i) (v_i - vbar_a) / (r_ia + 0.01 h) dW/dr_ia
//           (no-slip boundary: the velocity continued linearly to the dummy particle at depth d_a,
//           d_i the fluid particle's height above the surface; wall_rules.hpp. With the fluid's
//           Mirrored wall velocity, the paper's 2 (v_i - vbar_a): v^d = 2 vbar_a - v_i, METHOD.md
//           section 3; with the Quadratic one, continued as a parabola whose curvature is the
//           wall's momentum balance with b, the body force)
// With the lattice correction (default) both sums are divided by M2, the operator's value for a
// unit Laplacian on a regular lattice (kernel/lattice_moments.hpp).
// The fluid-fluid and fluid-boundary parts go into F^prior; each boundary pair force is kept so the
// boundary receives its exact opposite.
#pragma once

#include "fluid/fluid_body.hpp"

namespace mrsph {

// body_acceleration: b at the advection step's start (the quadratic wall rule's drive; no default, so
// that a caller cannot drop it silently).
void compute_viscous_force(FluidBody& fluid, const NeighborList& inner, std::vector<FluidContact>& contacts,
                           const Vec2& body_acceleration);

}  // namespace mrsph
