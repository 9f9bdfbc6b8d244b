// Elastic constitutive models in plane strain (paper section 2.1). With C = F^T F, J = det F and
// the Green-Lagrange strain E = (C - I)/2 (Eq. 9):
//   Saint Venant-Kirchhoff ("linear elastic", Eq. 10):  S = lambda tr(E) I + 2 G E
//   Neo-Hookean (Eqs. 12-13):  W = G tr(E) - G ln J + lambda/2 (ln J)^2,
//                              S = dW/dE = G (I - C^-1) + lambda ln J C^-1
// Both give S = lambda tr(E) I + 2 G E for small strain. First Piola-Kirchhoff P = F S (Eq. 8).
// Moduli: G = E / (2 (1 + nu)) (the paper's Eq. 11 has a typo), lambda = E nu / ((1 + nu)(1 - 2 nu)),
// K = E / (3 (1 - 2 nu)), sound speed c = sqrt(K / rho0).
#pragma once

#include "core/types.hpp"

#include <string>

namespace mrsph {

enum class SolidModel { SaintVenantKirchhoff, NeoHookean };

class ElasticMaterial {
 public:
  ElasticMaterial(SolidModel model, Real density, Real youngs_modulus, Real poisson_ratio);

  SolidModel model() const { return model_; }
  Real density() const { return rho0_; }
  Real youngs_modulus() const { return E_; }
  Real poisson_ratio() const { return nu_; }
  Real lambda() const { return lambda_; }
  Real shear_modulus() const { return G_; }
  Real bulk_modulus() const { return K_; }
  Real sound_speed() const { return c_; }

  Mat2 second_piola_kirchhoff(const Mat2& F) const;
  Mat2 first_piola_kirchhoff(const Mat2& F) const { return F * second_piola_kirchhoff(F); }
  Real strain_energy_density(const Mat2& F) const;  // per unit reference volume

 private:
  SolidModel model_;
  Real rho0_, E_, nu_, lambda_, G_, K_, c_;
};

SolidModel solid_model_from_name(const std::string& name);  // throws std::invalid_argument
std::string solid_model_name(SolidModel model);

}  // namespace mrsph
