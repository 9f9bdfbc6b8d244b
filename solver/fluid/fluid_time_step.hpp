// Dual-criteria time stepping of the fluid (Zhang, Rezavand & Hu 2020; paper Eqs. 32-33, with the
// terms of the paper's code, METHOD.md section 2):
//   advection:  Dt = 0.25 h / max( sqrt(max_i max(|v_i|^2, 4 h |a_i|)), U_ref, nu / h )
//               with a_i = f^d_i/m_i + g and nu = mu / rho0 (the h^2/nu viscous limit). The viscous
//               force is not in a_i: its limit is the h^2/nu term, and the paper's code resets
//               F^prior to the body force before evaluating Dt (METHOD.md section 6); at most the
//               fluid option max_advection_step where a scene sets one;
//   acoustic:   dt = 0.6 h / max_i (c + |v_i|).
#pragma once

#include "fluid/fluid_body.hpp"

namespace mrsph {

Real advection_time_step(const FluidBody& fluid, const Vec2& body_acceleration);
Real acoustic_time_step(const FluidBody& fluid);

}  // namespace mrsph
