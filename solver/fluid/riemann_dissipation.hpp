// Dissipation of the low-dissipation Riemann solver of Zhang, Hu & Adams (2017), split as in the
// paper's code (METHOD.md section 2). For a pair with u = (v_i - v_j).e_ij and Z = rho0 c:
//   continuity:  (p_i - p_j) / Z            (no limiter)
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
  Real limiter_eta = 3.0;
  Real impedance = 10.0;    // Z = rho0 c
  Real sound_speed = 10.0;

  // Per-pair terms; the reciprocals are set by configure() (no division in the pair loops).
  Real continuity_term(Real p_i, Real p_j) const { return (p_i - p_j) * inverse_impedance_; }
  // The sign of u is a coin toss from pair to pair, so max(s, 0) is written without a branch on
  // it: (s + |s|) / 2, exact in floating point (the compiler emitted a compare and a mispredicted
  // jump for std::max here).
  Real momentum_coefficient(Real u) const {
    const Real s = damp_separating ? u : -u;
    const Real jump = 0.5 * (s + std::abs(s));
    return impedance * u * std::min(jump * eta_over_sound_speed_, Real(1));
  }
  void configure(Real rho0, Real c) {
    impedance = rho0 * c;
    sound_speed = c;
    inverse_impedance_ = 1.0 / impedance;
    eta_over_sound_speed_ = limiter_eta / c;
  }

 private:
  Real inverse_impedance_ = 0.1;
  Real eta_over_sound_speed_ = 0.3;

 public:
};

}  // namespace mrsph
