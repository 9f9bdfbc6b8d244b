// Dissipation of the low-dissipation Riemann solver of Zhang, Hu & Adams (2017), split as in the
// paper's code (METHOD.md section 2). For a pair with u = (v_i - v_j).e_ij and Z = rho0 c:
//   continuity:  (p_i - p_j) / Z            (no limiter)
//   momentum:    Pi(u) = Z u beta,  beta = min(eta max(-u, 0) / c, 1), eta = 3
// The paper damps approaching (compressing, u < 0) pairs; the code since 2022 damps separating
// pairs (u > 0). Approaching is the default; `damp_separating` keeps the other for comparison.
#pragma once

#include "core/types.hpp"

#include <algorithm>

namespace mrsph {

struct RiemannDissipation {
  bool continuity = true;   // "1st-half Riemann": pressure difference in the continuity equation
  bool momentum = false;    // "2nd-half Riemann": velocity jump in the momentum equation
  bool damp_separating = false;
  Real limiter_eta = 3.0;
  Real impedance = 10.0;    // Z = rho0 c
  Real sound_speed = 10.0;

  Real continuity_term(Real p_i, Real p_j) const { return (p_i - p_j) / impedance; }
  Real momentum_coefficient(Real u) const {
    const Real jump = damp_separating ? std::max(u, Real(0)) : std::max(-u, Real(0));
    return impedance * u * std::min(limiter_eta * jump / sound_speed, Real(1));
  }
};

}  // namespace mrsph
