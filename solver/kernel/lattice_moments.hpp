// Sums of the kernel over a square lattice of spacing dp (origin at a particle): the discrete
// counterparts of integrals the SPH operators rely on. On a regular particle distribution they
// differ from their continuum values by a fixed amount at fixed h/dp, which no refinement removes.
//   number density  sigma0 = sum_k W(|x_k|)                        continuum: 1 / dp^2
//   gradient        M1 = -sum_{k != 0} dp^2 x_k^2 W'(r_k) / r_k             continuum: 1
//   Laplacian       M2 = -sum_{k != 0} dp^2 y_k^2 W'(r_k) / (r_k + eps)   continuum: 1
// M1 is what the gradient sum_j V_j (f_j - f_i) grad_i W_ij (and the pressure force's
// sum_j V_j (p_i + p_j) grad_i W_ij) returns for f = x: 0.974 for Wendland C2 with h = 1.3 dp, so a
// linear pressure field pushes 2.6 % less than its gradient (reports/open-boundaries.md).
// M2 is what the Morris viscous operator 2 sum_j V_j (u_i - u_j) W'_ij / (r_ij + eps) returns for
// u = y^2 / 2 (whose Laplacian is 1): 0.964 for Wendland C2 with h = 1.3 dp and eps = 0.01 h.
#pragma once

#include "kernel/wendland_c2.hpp"

namespace mrsph {

Real lattice_number_density(const WendlandC2& kernel, Real dp);
Real lattice_gradient_moment(const WendlandC2& kernel, Real dp);
Real lattice_laplacian_moment(const WendlandC2& kernel, Real dp, Real regularisation);

}  // namespace mrsph
