// Saint Venant-Kirchhoff ("linear elastic", paper Eq. 10), in plane strain (F_zz = 1). With
// C = F^T F and the Green-Lagrange strain E = (C - I) / 2 (Eq. 9):
//   S = lambda tr(E) I + 2 G E,   W = lambda/2 tr(E)^2 + G E:E,   S_zz = lambda tr(E)  (E_zz = 0)
#pragma once

#include "solid/constitutive/elastic_moduli.hpp"

#include <array>
#include <string_view>

namespace mrsph {

struct SaintVenantKirchhoff {
  static constexpr std::array<std::string_view, 2> names{"saint_venant_kirchhoff", "linear_elastic"};
  static constexpr std::array<ModelParameter, 0> parameters{};

  static Mat2 second_piola_kirchhoff(const ElasticModuli& m, const Mat2& F) {
    const Mat2 C = F.transpose() * F;
    return linear_elastic_stress(m, 0.5 * (C - Mat2::Identity()));
  }
  static Real strain_energy_density(const ElasticModuli& m, const Mat2& F) {
    const Mat2 strain = 0.5 * (F.transpose() * F - Mat2::Identity());
    return 0.5 * m.lambda * strain.trace() * strain.trace() + m.shear * (strain * strain).trace();
  }
  static Real out_of_plane_stress(const ElasticModuli& m, const Mat2& F) {
    const Mat2 C = F.transpose() * F;
    return m.lambda * 0.5 * (C.trace() - 2.0);
  }
};

}  // namespace mrsph
