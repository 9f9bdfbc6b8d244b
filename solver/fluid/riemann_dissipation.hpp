// Dissipation of the low-dissipation Riemann solver of Zhang, Hu & Adams (2017), split as in the
// paper's code (METHOD.md section 2). For a pair with u = (v_i - v_j).e_ij and Z = rho0 c:
//   continuity:  (p_i - p_j - rho0 b.r_ij) / Z      (no limiter; r_ij = r_i - r_j)
// b is the body force per unit mass. The paper's term is (p_i - p_j) / Z. Here it acts on the
// pressure's departure from the rest state p = rho0 b.r + const, the well-balanced form
// (`hydrostatic_balance`, the default). On a cut support, at a free surface, the paper's term is
// not zero for a column at rest. It raises the density there by about rho g / c (reports/pressure.md
// section 12). Only b's components along axes that are not periodic count: along a periodic axis
// the pressure has no mean gradient, and a force there drives a flow instead (a channel). With the
// fluid's rest_state_at_walls the wall rule's pressure continues the same rest state into the dummy
// particles (wall_rules.hpp), so a column at rest is balanced across walls too.
//   momentum:    Pi(u) = Z u beta,  beta = min(eta max(-u, 0) / c, 1), eta = 3
// The paper damps approaching (compressing, u < 0) pairs; the code since 2022 damps separating
// pairs (u > 0). Approaching is the default; `damp_separating` keeps the other for comparison.
#pragma once

#include "core/types.hpp"

#include <algorithm>
#include <cmath>

namespace mrsph {

struct RiemannDissipation {
 public:
  bool continuity = true;   // "1st-half Riemann": pressure difference in the continuity equation
  bool momentum = false;    // "2nd-half Riemann": velocity jump in the momentum equation
  bool damp_separating = false;
  bool hydrostatic_balance = true;  // false: the paper's (p_i - p_j) / Z
  Real limiter_eta = 3.0;
  Real impedance = 10.0;    // Z = rho0 c
  Real sound_speed = 10.0;

  // Per-pair terms; the reciprocals are set by configure() (no division in the pair loops).
  Real continuity_term(Real p_i, Real p_j) const { return (p_i - p_j) * inverse_impedance_; }
  // The same with the rest state's pressure difference rest_gradient.r_ij taken out.
  Real continuity_term(Real p_i, Real p_j, const Vec2& rest_gradient, const Vec2& r_ij) const {
    return (p_i - p_j - rest_gradient.dot(r_ij)) * inverse_impedance_;
  }
  // b along the axes that can hold a rest state (zero without the balance).
  Vec2 rest_acceleration(const Vec2& body_acceleration) const {
    return hydrostatic_balance ? Vec2(body_acceleration.cwiseProduct(rest_axes_)) : Vec2::Zero();
  }
  // rho0 b, the rest state's pressure gradient (zero without the balance).
  Vec2 rest_pressure_gradient(const Vec2& body_acceleration) const {
    return rho0_ * rest_acceleration(body_acceleration);
  }
  // Which axes can hold a rest state's pressure gradient (1) and which are periodic (0).
  void set_periodic_axes(bool periodic_x, bool periodic_y) {
    rest_axes_ = Vec2(periodic_x ? 0.0 : 1.0, periodic_y ? 0.0 : 1.0);
  }
  // The sign of u is a coin toss from pair to pair, so max(s, 0) is written without a branch on
  // it: (s + |s|) / 2, exact in floating point (the compiler emitted a compare and a mispredicted
  // jump for std::max here).
  Real momentum_coefficient(Real u) const {
    const Real s = damp_separating ? u : -u;
    const Real jump = 0.5 * (s + std::abs(s));
    return impedance * u * std::min(jump * eta_over_sound_speed_, Real(1));
  }
  void configure(Real rho0, Real c) {
    rho0_ = rho0;
    impedance = rho0 * c;
    sound_speed = c;
    inverse_impedance_ = 1.0 / impedance;
    eta_over_sound_speed_ = limiter_eta / c;
  }

 private:
  Real rho0_ = 1.0;
  Vec2 rest_axes_ = Vec2(1.0, 1.0);
  Real inverse_impedance_ = 0.1;
  Real eta_over_sound_speed_ = 0.3;

 public:
};

}  // namespace mrsph
