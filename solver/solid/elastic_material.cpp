#include "solid/elastic_material.hpp"

#include <cmath>
#include <stdexcept>

namespace mrsph {

ElasticMaterial::ElasticMaterial(SolidModel model, Real density, Real youngs_modulus, Real poisson_ratio)
    : model_(model), rho0_(density), E_(youngs_modulus), nu_(poisson_ratio) {
  if (!(density > 0.0)) throw std::invalid_argument("density must be positive");
  if (!(youngs_modulus > 0.0)) throw std::invalid_argument("Young's modulus must be positive");
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5)) throw std::invalid_argument("Poisson ratio must lie in (-1, 0.5)");
  G_ = E_ / (2.0 * (1.0 + nu_));
  lambda_ = E_ * nu_ / ((1.0 + nu_) * (1.0 - 2.0 * nu_));
  K_ = E_ / (3.0 * (1.0 - 2.0 * nu_));
  c_ = std::sqrt(K_ / rho0_);
}

Mat2 ElasticMaterial::second_piola_kirchhoff(const Mat2& F) const {
  const Mat2 C = F.transpose() * F;
  if (model_ == SolidModel::SaintVenantKirchhoff) {
    const Mat2 strain = 0.5 * (C - Mat2::Identity());
    return lambda_ * strain.trace() * Mat2::Identity() + 2.0 * G_ * strain;
  }
  const Real J = F.determinant();
  const Mat2 C_inv = C.inverse();
  return G_ * (Mat2::Identity() - C_inv) + lambda_ * std::log(J) * C_inv;
}

Real ElasticMaterial::strain_energy_density(const Mat2& F) const {
  const Mat2 C = F.transpose() * F;
  const Mat2 strain = 0.5 * (C - Mat2::Identity());
  if (model_ == SolidModel::SaintVenantKirchhoff)
    return 0.5 * lambda_ * strain.trace() * strain.trace() + G_ * (strain * strain).trace();
  const Real log_J = std::log(F.determinant());
  return G_ * strain.trace() - G_ * log_J + 0.5 * lambda_ * log_J * log_J;
}

SolidModel solid_model_from_name(const std::string& name) {
  if (name == "saint_venant_kirchhoff" || name == "linear_elastic") return SolidModel::SaintVenantKirchhoff;
  if (name == "neo_hookean") return SolidModel::NeoHookean;
  throw std::invalid_argument("unknown solid model '" + name +
                              "', expected \"saint_venant_kirchhoff\" (alias \"linear_elastic\") or \"neo_hookean\"");
}

std::string solid_model_name(SolidModel model) {
  return model == SolidModel::SaintVenantKirchhoff ? "saint_venant_kirchhoff" : "neo_hookean";
}

}  // namespace mrsph
