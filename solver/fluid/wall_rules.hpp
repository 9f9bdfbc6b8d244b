// How a fluid particle i sees a wall or solid particle a (a dummy particle of the boundary): the rules
// every fluid operator uses across a boundary, written once.
//
//   velocity   the no-slip mirror: the fluid's velocity relative to the boundary's averaged
//              velocity, doubled (paper Eqs. 29 and 31, of the Riemann momentum dissipation, and
//              of the viscous force with the fluid's Mirrored wall velocity; Adami et al. 2012):
//                                                                    2 (v_i - vbar_a)
//   continuity the wall term of the continuity equation, rho_i sum_a V_a (v_i - v^d_a).e_ia W'_ia.
//              Where the density is re-initialised by summation, the dummy moves with the
//              boundary, v^d_a = vbar_a:                              v_i - vbar_a
//              the term is then the time derivative of the summation's own wall term
//              (sum_a W_ia V_a), so between two summations the continuity equation carries the
//              density where the next summation will find it. The mirror (v^d_a = 2 vbar_a - v_i,
//              the paper's Eq. 31 and its code) moves it twice as fast as the summation does
//              wherever the fluid moves relative to a boundary; each re-initialisation then sets
//              the density back, a jump whose pressure is c^2 times the difference. Next to a
//              moving body this made FSI2's amplitude depend on c (0.850 at c = 10 U0, 0.929 at
//              40; with the summation's rule 0.820 and 0.817: reports/pressure.md section 22).
//              Without a re-initialisation nothing defines the density but the continuity
//              equation, and the mirror, a linear continuation of the velocity into the wall,
//              keeps its divergence first-order consistent there.
//   viscous    the velocity continued linearly through the wall (Morris et al. 1997; Macia et al.
//   velocity   2011 show the mirror's viscous operator inconsistent next to a wall): a dummy particle
//              at depth d_a below the surface, seen from a fluid particle at distance d_i above it,
//              moves with vbar_a - (d_a / d_i)(v_i - vbar_a):   (1 + d_a / d_i) (v_i - vbar_a)
//              The mirror gives every dummy -v_i, as if each lay as deep as the fluid particle is
//              high: a linear shear profile sees too little shear from the deeper dummies, a slip at
//              the wall that shrinks only with dp (a Poiseuille channel's profile converges at order
//              0.6 with it, about 2 with the continuation: reports/pressure.md section 20). d_i is
//              floored at dp / 4, so that a fluid particle pressed against the wall does not
//              amplify its velocity without bound.
//              The fluid's quadratic rule (an option) continues it as the parabola through vbar_a
//              and v_i whose curvature along the wall is the one the wall's momentum balance gives:
//              where the fluid sticks to the wall (v = vbar_a), Navier-Stokes leaves
//                nu d^2 v_t / dn^2 = (abar_a - a^p - b)_t          (t: along the wall, n: normal)
//              (a^p the pressure acceleration, b the body force; the normal part is left out), so
//              the dummy moves with the linear rule's velocity plus kappa d_a (d_i + d_a) / 2:
//                                  (1 + d_a / d_i) (v_i - vbar_a) - kappa d_a (d_i + d_a) / 2
//              exact for a parabolic profile (a channel driven by a body force: Womersley's error
//              2-17 times smaller at H/dp = 20-40, reports/pressure.md section 34), where the linear
//              rule's wall slips by -kappa d_a (d_i + d_a) / 2 (d_i, d_a up to 2 h). Its a^p is the
//              particle's, so the pressure's noise enters the wall term with it.
//   pressure   extrapolated from the fluid particle to the dummy particle (paper Eq. 30; Adami et
//              al. 2012), with the boundary's averaged acceleration. With the fluid's
//              rest_state_at_walls the rest state's pressure gradient G = rho0 b (b: the body force
//              along the axes that are not periodic, riemann_dissipation.hpp) is continued whole,
//              and the rest of the acceleration clipped at zero as the paper's code does (G = 0
//              without the option: the paper's clip of the whole acceleration):
//                p^d_ia = p_i + rho_i max(0, (a^prior_i - b - abar_a) . (r_a - r_i))
//                         + max(G . (r_a - r_i), min(-p_i, 0))
//              Clipped as a whole (b's part inside the max), a dummy above particle i (under a
//              body, beside a side wall) keeps p_i where the column at rest has p_i - rho0 g dy:
//              the dummies under a submerged cylinder push it up too hard, its buoyancy 2.2-4.1 %
//              above Archimedes at every c (reports/pressure.md section 19). The continuation does
//              not take the dummy below the atmosphere's 0 where p_i is above it: above a free
//              surface there is air.
//   direction  of the Riemann dissipation across a boundary: the boundary's normal, turned to face
//              the fluid particle (METHOD.md section 3)
#pragma once

#include "core/types.hpp"

#include <algorithm>

namespace mrsph {

inline Vec2 wall_velocity_difference(const Vec2& v_i, const Vec2& vbar_a) { return 2.0 * (v_i - vbar_a); }

// v_i - v^d_a in the continuity equation's wall term: the mirror's, or the summation's (above).
inline Vec2 wall_continuity_velocity_difference(const Vec2& v_i, const Vec2& vbar_a, bool mirrored) {
  return mirrored ? wall_velocity_difference(v_i, vbar_a) : Vec2(v_i - vbar_a);
}

// d_i: the fluid particle's distance above the surface (wall_distance_from_nearest), already floored.
inline Vec2 wall_viscous_velocity_difference(const Vec2& v_i, const Vec2& vbar_a, Real d_i, Real d_a) {
  return (1.0 + d_a / d_i) * (v_i - vbar_a);
}

// kappa: the profile's curvature along the wall, -(drive - (drive . n) n) / nu, with
// drive = a^p_i + b - abar_a and n the wall's normal (above).
inline Vec2 wall_profile_curvature(const Vec2& drive, const Vec2& n, Real nu) {
  return -(drive - drive.dot(n) * n) / nu;
}

// What the quadratic rule adds to v_i - v^d_a (above).
inline Vec2 wall_viscous_curvature_difference(const Vec2& curvature, Real d_i, Real d_a) {
  return (-0.5 * d_a * (d_i + d_a)) * curvature;
}

// d_i from the boundary particle a nearest to i (e_ia from a to i, r_ia their distance, n_a its
// normal, d_a its depth): the height of i above a's tangent, r_ia e_ia . n_a - d_a, floored at `floor`.
// The nearest particle lies almost straight below i, so a curved surface's tangent errs little there.
inline Real wall_distance_from_nearest(Real r_ia, const Vec2& e_ia, const Vec2& n_a, Real d_a, Real floor) {
  return std::max(floor, r_ia * e_ia.dot(n_a) - d_a);
}

// acc_beyond_rest_i: a^prior_i - b. With G = 0 this is the paper's rule to the bit.
inline Real wall_pressure(Real p_i, Real rho_i, const Vec2& acc_beyond_rest_i, const Vec2& abar_a, const Vec2& r_ai,
                          const Vec2& rest_gradient) {
  return p_i + rho_i * std::max(Real(0), (acc_beyond_rest_i - abar_a).dot(r_ai)) +
         std::max(rest_gradient.dot(r_ai), std::min(-p_i, Real(0)));
}

// e_ia points from a to i; n_a is the boundary particle's normal.
inline Vec2 wall_normal_towards_fluid(const Vec2& e_ia, const Vec2& n_a) { return e_ia.dot(n_a) >= 0.0 ? n_a : Vec2(-n_a); }

}  // namespace mrsph
