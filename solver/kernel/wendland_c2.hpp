// Wendland C2 kernel in 2D (the paper's "5th-order Wendland"), support radius 2h.
//   q = r/h,  W(r) = 7/(4 pi h^2) (1 - q/2)^4 (1 + 2q),  dW/dr = -35/(4 pi h^3) q (1 - q/2)^3,
//   d2W/dr2 = -35/(4 pi h^4) (1 - q/2)^2 (1 - 2q).
// Source: Wendland (1995); normalisation for 2D as in METHOD.md section 1.
#pragma once

#include "core/types.hpp"

namespace mrsph {

class WendlandC2 {
 public:
  explicit WendlandC2(Real h);

  Real h() const { return h_; }
  Real cutoff() const { return 2.0 * h_; }
  Real W(Real r) const {
    const Real q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    const Real a = 1.0 - 0.5 * q;
    const Real a2 = a * a;
    return factor_W_ * a2 * a2 * (1.0 + 2.0 * q);
  }
  // dW/dr <= 0.
  Real dW(Real r) const {
    const Real q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    const Real a = 1.0 - 0.5 * q;
    return factor_dW_ * q * a * a * a;
  }
  // dW/dr / r, without a division: 35/(4 pi h^4) (1 - q/2)^3.
  Real dW_over_r(Real r) const {
    const Real q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    const Real a = 1.0 - 0.5 * q;
    return factor_dW_ * inv_h_ * a * a * a;
  }
  // d2W/dr2 (the stiffness of a pair potential built on W: solid/solid_contact.hpp).
  Real d2W(Real r) const {
    const Real q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    const Real a = 1.0 - 0.5 * q;
    return factor_dW_ * inv_h_ * a * a * (1.0 - 2.0 * q);
  }
  Real W0() const { return factor_W_; }
  // W and dW/dr together (shared terms), for r < cutoff.
  void values(Real r, Real& w, Real& dw) const {
    const Real q = r * inv_h_;
    const Real a = 1.0 - 0.5 * q;
    const Real a3 = a * a * a;
    w = factor_W_ * a3 * a * (1.0 + 2.0 * q);
    dw = factor_dW_ * q * a3;
  }

 private:
  Real h_, inv_h_, factor_W_, factor_dW_;
};

}  // namespace mrsph
