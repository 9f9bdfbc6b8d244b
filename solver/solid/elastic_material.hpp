// An elastic material in plane strain (paper section 2.1): density, the moduli from Young's modulus
// and Poisson's ratio, and one of the constitutive models of constitutive/elastic_models.hpp, which
// give the stress and energy. First Piola-Kirchhoff P = F S (Eq. 8). Bulk modulus
// K = E / (3 (1 - 2 nu)), sound speed c = sqrt(K / rho0).
#pragma once

#include "core/types.hpp"
#include "solid/constitutive/elastic_models.hpp"

#include <string>

namespace mrsph {

class ElasticMaterial {
 public:
  ElasticMaterial(ElasticModel model, Real density, Real youngs_modulus, Real poisson_ratio);

  std::string model_name() const { return elastic_model_name(model_); }
  Real density() const { return rho0_; }
  Real youngs_modulus() const { return E_; }
  Real poisson_ratio() const { return nu_; }
  Real lambda() const { return moduli_.lambda; }
  Real shear_modulus() const { return moduli_.shear; }
  const ElasticModuli& moduli() const { return moduli_; }
  Real bulk_modulus() const { return K_; }
  Real sound_speed() const { return c_; }

  Mat2 second_piola_kirchhoff(const Mat2& F) const {
    return std::visit([&](const auto& m) { return m.second_piola_kirchhoff(moduli_, F); }, model_);
  }
  Mat2 first_piola_kirchhoff(const Mat2& F) const { return F * second_piola_kirchhoff(F); }
  Real strain_energy_density(const Mat2& F) const {  // per unit reference volume
    return std::visit([&](const auto& m) { return m.strain_energy_density(moduli_, F); }, model_);
  }
  // S_zz of plane strain (F_zz = 1): the out-of-plane stress the von Mises stress needs.
  Real out_of_plane_stress(const Mat2& F) const {
    return std::visit([&](const auto& m) { return m.out_of_plane_stress(moduli_, F); }, model_);
  }

 private:
  ElasticModel model_;
  Real rho0_, E_, nu_;
  ElasticModuli moduli_{};
  Real K_, c_;
};

}  // namespace mrsph
