// The small-strain moduli every elastic model is parametrised by (paper section 2.1): with Young's
// modulus E and Poisson's ratio nu, G = E / (2 (1 + nu)) (the paper's Eq. 11 has a typo) and
// lambda = E nu / ((1 + nu)(1 - 2 nu)). Every model linearises to S = lambda tr(E) I + 2 G E.
#pragma once

#include "core/types.hpp"

#include <string_view>

namespace mrsph {

struct ElasticModuli {
  Real lambda;
  Real shear;  // G
};

// A model's own scene parameter (beyond the moduli): read from the material's JSON object by its key,
// `fallback` when absent, refused outside [lower, upper].
struct ModelParameter {
  std::string_view key;
  Real fallback, lower, upper;
  std::string_view meaning;
};

// The small-strain stress lambda tr(e) I + 2 G e of a symmetric strain e (plane strain).
inline Mat2 linear_elastic_stress(const ElasticModuli& m, const Mat2& strain) {
  return m.lambda * strain.trace() * Mat2::Identity() + 2.0 * m.shear * strain;
}

}  // namespace mrsph
