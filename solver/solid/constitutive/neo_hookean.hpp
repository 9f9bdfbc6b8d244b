// Neo-Hookean (paper Eqs. 12-13), in plane strain (F_zz = 1). With C = F^T F, J = det F and
// E = (C - I) / 2:
//   W = G tr(E) - G ln J + lambda/2 (ln J)^2,   S = dW/dE = G (I - C^-1) + lambda ln J C^-1,
//   S_zz = lambda ln J  (C_zz = 1)
#pragma once

#include "solid/constitutive/elastic_moduli.hpp"

#include <array>
#include <cmath>
#include <string_view>

namespace mrsph {

struct NeoHookean {
  static constexpr std::array<std::string_view, 1> names{"neo_hookean"};
  static constexpr std::array<ModelParameter, 0> parameters{};

  static Mat2 second_piola_kirchhoff(const ElasticModuli& m, const Mat2& F) {
    const Mat2 C = F.transpose() * F;
    const Real J = F.determinant();
    const Mat2 C_inv = C.inverse();
    return m.shear * (Mat2::Identity() - C_inv) + m.lambda * std::log(J) * C_inv;
  }
  static Real strain_energy_density(const ElasticModuli& m, const Mat2& F) {
    const Mat2 strain = 0.5 * (F.transpose() * F - Mat2::Identity());
    const Real log_J = std::log(F.determinant());
    return m.shear * strain.trace() - m.shear * log_J + 0.5 * m.lambda * log_J * log_J;
  }
  static Real out_of_plane_stress(const ElasticModuli& m, const Mat2& F) { return m.lambda * std::log(F.determinant()); }
};

}  // namespace mrsph
