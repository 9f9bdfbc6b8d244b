// Weakly-compressible equations of state.
//   Tait (paper Eq. 3):  p = rho0 c^2 / gamma ((rho / rho0)^gamma - 1), gamma = 7.
//   Linear (the paper's code): p = c^2 (rho - rho0); the same as Tait to first order in rho - rho0.
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

  Real pressure(Real rho) const {
    if (kind == EquationOfStateKind::Linear) return c0 * c0 * (rho - rho0);
    return rho0 * c0 * c0 / gamma * (std::pow(rho / rho0, gamma) - 1.0);
  }
  Real density(Real p) const {
    if (kind == EquationOfStateKind::Linear) return rho0 + p / (c0 * c0);
    return rho0 * std::pow(1.0 + gamma * p / (rho0 * c0 * c0), 1.0 / gamma);
  }
  // Acoustic impedance rho0 c0 used by the Riemann solver.
  Real impedance() const { return rho0 * c0; }
};

}  // namespace mrsph
