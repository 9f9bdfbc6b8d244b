// How a fluid particle i sees a wall or solid particle a (a dummy particle of the boundary): the rules
// every fluid operator uses across a boundary, written once.
//
//   velocity   the no-slip mirror: the fluid's velocity relative to the boundary's averaged
//              velocity, doubled (paper Eqs. 29 and 31, the wall term of the viscous force and of
//              the continuity equation; Adami et al. 2012):        2 (v_i - vbar_a)
//   pressure   extrapolated from the fluid particle to the dummy particle (paper Eq. 30; Adami et
//              al. 2012), with the boundary's averaged acceleration:
//                p^d_ia = p_i + rho_i max(0, (a^prior_i - abar_a) . (r_a - r_i))
//   direction  of the Riemann dissipation across a boundary: the boundary's normal, turned to face
//              the fluid particle (METHOD.md section 3)
#pragma once

#include "core/types.hpp"

#include <algorithm>

namespace mrsph {

inline Vec2 wall_velocity_difference(const Vec2& v_i, const Vec2& vbar_a) { return 2.0 * (v_i - vbar_a); }

inline Real wall_pressure(Real p_i, Real rho_i, const Vec2& acc_prior_i, const Vec2& abar_a, const Vec2& r_ai) {
  return p_i + rho_i * std::max(Real(0), (acc_prior_i - abar_a).dot(r_ai));
}

// e_ia points from a to i; n_a is the boundary particle's normal.
inline Vec2 wall_normal_towards_fluid(const Vec2& e_ia, const Vec2& n_a) { return e_ia.dot(n_a) >= 0.0 ? n_a : Vec2(-n_a); }

}  // namespace mrsph
