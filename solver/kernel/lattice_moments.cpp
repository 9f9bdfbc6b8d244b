#include "kernel/lattice_moments.hpp"

#include <cmath>

namespace mrsph {

namespace {
template <class Term>
Real lattice_sum(const WendlandC2& kernel, Real dp, Term term) {
  const int n = static_cast<int>(std::ceil(kernel.cutoff() / dp)) + 1;
  Real sum = 0.0;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j) sum += term(Real(i) * dp, Real(j) * dp);
  return sum;
}
}  // namespace

Real lattice_number_density(const WendlandC2& kernel, Real dp) {
  return lattice_sum(kernel, dp, [&](Real x, Real y) { return kernel.W(std::hypot(x, y)); });
}

Real lattice_laplacian_moment(const WendlandC2& kernel, Real dp, Real regularisation) {
  return lattice_sum(kernel, dp, [&](Real x, Real y) {
    const Real r = std::hypot(x, y);
    return r > 0.0 ? -dp * dp * y * y * kernel.dW(r) / (r + regularisation) : 0.0;
  });
}

Real lattice_gradient_moment(const WendlandC2& kernel, Real dp) {
  return lattice_sum(kernel, dp, [&](Real x, Real y) {
    const Real r = std::hypot(x, y);
    return r > 0.0 ? -dp * dp * x * x * kernel.dW(r) / r : 0.0;
  });
}

}  // namespace mrsph
