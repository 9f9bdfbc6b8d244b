#include "solid/elastic_material.hpp"

#include <cmath>
#include <stdexcept>

namespace mrsph {

ElasticMaterial::ElasticMaterial(ElasticModel model, Real density, Real youngs_modulus, Real poisson_ratio)
    : model_(model), rho0_(density), E_(youngs_modulus), nu_(poisson_ratio) {
  if (!(density > 0.0)) throw std::invalid_argument("density must be positive");
  if (!(youngs_modulus > 0.0)) throw std::invalid_argument("Young's modulus must be positive");
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5)) throw std::invalid_argument("Poisson ratio must lie in (-1, 0.5)");
  moduli_.shear = E_ / (2.0 * (1.0 + nu_));
  moduli_.lambda = E_ * nu_ / ((1.0 + nu_) * (1.0 - 2.0 * nu_));
  K_ = E_ / (3.0 * (1.0 - 2.0 * nu_));
  c_ = std::sqrt(K_ / rho0_);
}

}  // namespace mrsph
