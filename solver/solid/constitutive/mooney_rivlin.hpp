// Mooney-Rivlin, compressible, with the isochoric-volumetric split (Holzapfel 2000, sections 6.4-6.5),
// in plane strain (F_zz = 1). With C3 = diag(C, 1), J = det F, I1 = tr C3,
// I2 = ((tr C3)^2 - tr(C3^2)) / 2 and the isochoric invariants I1b = J^(-2/3) I1, I2b = J^(-4/3) I2:
//   W = C10 (I1b - 3) + C01 (I2b - 3) + K/2 (ln J)^2
//   S = 2 dW/dC = 2 C10 J^(-2/3) (I - I1/3 C^-1) + 2 C01 J^(-4/3) (I1 I - C - 2/3 I2 C^-1) + K ln J C^-1
//   S_zz: the same with C_zz = (C^-1)_zz = 1
// From the moduli: 2 (C10 + C01) = G and K = lambda + 2 G / 3, so it linearises to the same
// S = lambda tr(E) I + 2 G E as every model. Its own parameter c01_fraction = C01 / (C10 + C01)
// (0: the isochoric neo-Hookean). In simple shear (J = 1) its Cauchy shear stress is G gamma exactly.
#pragma once

#include "solid/constitutive/elastic_moduli.hpp"

#include <array>
#include <cmath>
#include <span>
#include <string_view>

namespace mrsph {

struct MooneyRivlin {
  static constexpr std::array<std::string_view, 1> names{"mooney_rivlin"};
  static constexpr std::array<ModelParameter, 1> parameters{
      {{"c01_fraction", 0.0, 0.0, 1.0, "C01 / (C10 + C01): the share of the shear modulus on the second invariant"}}};
  static MooneyRivlin from(std::span<const Real> values) { return {values[0]}; }

  Real c01_fraction = 0.0;

  // C10, C01 and K of the header from the moduli.
  struct Constants {
    Real c10, c01, bulk;
  };
  Constants constants(const ElasticModuli& m) const {
    return {0.5 * (1.0 - c01_fraction) * m.shear, 0.5 * c01_fraction * m.shear, m.lambda + 2.0 * m.shear / 3.0};
  }
  // I1 and I2 of C3 = diag(C, 1).
  static std::array<Real, 2> invariants(const Mat2& C) {
    const Real I1 = C.trace() + 1.0;
    return {I1, 0.5 * (I1 * I1 - ((C * C).trace() + 1.0))};
  }

  Mat2 second_piola_kirchhoff(const ElasticModuli& m, const Mat2& F) const {
    const Mat2 C = F.transpose() * F, C_inv = C.inverse(), I = Mat2::Identity();
    const Real J = F.determinant();
    const auto [I1, I2] = invariants(C);
    const Constants k = constants(m);
    return 2.0 * k.c10 * std::pow(J, -2.0 / 3.0) * (I - I1 / 3.0 * C_inv) +
           2.0 * k.c01 * std::pow(J, -4.0 / 3.0) * (I1 * I - C - 2.0 / 3.0 * I2 * C_inv) + k.bulk * std::log(J) * C_inv;
  }
  Real strain_energy_density(const ElasticModuli& m, const Mat2& F) const {
    const Real J = F.determinant();
    const auto [I1, I2] = invariants(F.transpose() * F);
    const Constants k = constants(m);
    return k.c10 * (std::pow(J, -2.0 / 3.0) * I1 - 3.0) + k.c01 * (std::pow(J, -4.0 / 3.0) * I2 - 3.0) +
           0.5 * k.bulk * std::log(J) * std::log(J);
  }
  Real out_of_plane_stress(const ElasticModuli& m, const Mat2& F) const {
    const Real J = F.determinant();
    const auto [I1, I2] = invariants(F.transpose() * F);
    const Constants k = constants(m);
    return 2.0 * k.c10 * std::pow(J, -2.0 / 3.0) * (1.0 - I1 / 3.0) +
           2.0 * k.c01 * std::pow(J, -4.0 / 3.0) * (I1 - 1.0 - 2.0 / 3.0 * I2) + k.bulk * std::log(J);
  }
};

}  // namespace mrsph
