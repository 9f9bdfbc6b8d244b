// Weakly-compressible equations of state, with an optional background pressure p_b (0 in the paper):
//   Tait (paper Eq. 3):  p = p_b + rho0 c^2 / gamma ((rho / rho0)^gamma - 1), gamma = 7.
//   Linear (the paper's code): p = p_b + c^2 (rho - rho0); the same as Tait to first order in rho - rho0.
// p_b is the pressure of the fluid at rest at rho0: a vein's transmural pressure under open
// boundaries, which keeps the fluid out of tension where the flow draws the pressure down.
#pragma once

#include "core/types.hpp"

#include <cmath>

namespace mrsph {

enum class EquationOfStateKind { Linear, Tait };

struct EquationOfState {
  EquationOfStateKind kind = EquationOfStateKind::Linear;
  Real rho0 = 1.0;
  Real c0 = 10.0;
  Real gamma = 7.0;
  Real background = 0.0;  // p_b

  Real pressure(Real rho) const {
    if (kind == EquationOfStateKind::Linear) return background + c0 * c0 * (rho - rho0);
    return background + rho0 * c0 * c0 / gamma * (std::pow(rho / rho0, gamma) - 1.0);
  }
  Real density(Real p) const {
    if (kind == EquationOfStateKind::Linear) return rho0 + (p - background) / (c0 * c0);
    return rho0 * std::pow(1.0 + gamma * (p - background) / (rho0 * c0 * c0), 1.0 / gamma);
  }
  // Internal energy per unit mass, e(rho) = integral from rho0 to rho of p(s) / s^2 ds (de = p / rho^2
  // drho): with the kinetic energy, what an undamped fluid conserves (reports/pressure.md section 9).
  Real internal_energy(Real rho) const {
    const Real expansion = 1.0 / rho0 - 1.0 / rho;
    if (kind == EquationOfStateKind::Linear) return background * expansion + c0 * c0 * (std::log(rho / rho0) - rho0 * expansion);
    const Real B = rho0 * c0 * c0 / gamma;
    return (background - B) * expansion + B / (rho0 * (gamma - 1.0)) * (std::pow(rho / rho0, gamma - 1.0) - 1.0);
  }
  // Acoustic impedance rho0 c0 used by the Riemann solver.
  Real impedance() const { return rho0 * c0; }
};

}  // namespace mrsph
