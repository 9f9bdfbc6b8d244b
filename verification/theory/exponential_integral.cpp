#include "theory/exponential_integral.hpp"

#include <cmath>
#include <stdexcept>

namespace mrsph::verification::theory {

namespace {

using C = std::complex<double>;
constexpr double euler_gamma = 0.57721566490153286;

// E1(z) = -gamma - ln z - sum_{k>=1} (-z)^k / (k k!) (A&S 5.1.11). Accurate where E1 is not much
// smaller than the series' largest term (about e^|z|): small |z|, and near the negative real axis,
// where E1 itself grows like e^{-Re z}. Summed in long double.
C series(C z) {
  using L = std::complex<long double>;
  const L zl(z.real(), z.imag());
  L sum = 0.0L, term = 1.0L;
  for (int k = 1; k < 600; ++k) {
    term *= -zl / static_cast<long double>(k);
    sum += term / static_cast<long double>(k);
    if (std::abs(term) < 1e-19L * std::abs(sum)) break;
  }
  const L value = -static_cast<long double>(euler_gamma) - std::log(zl) - sum;
  return C(double(value.real()), double(value.imag()));
}

// E1(z) = e^{-z} / (z + 1 - 1^2 / (z + 3 - 2^2 / (z + 5 - ...))) (A&S 5.1.22), modified Lentz; fast
// except near the negative real axis.
C continued_fraction(C z) {
  constexpr double tiny = 1e-300;
  C b = z + 1.0, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 5000; ++i) {
    const double a = -double(i) * double(i);
    b += 2.0;
    d = 1.0 / (a * d + b);
    c = b + a / c;
    const C delta = c * d;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) return h * std::exp(-z);
  }
  throw std::runtime_error("exponential integral E1: continued fraction did not converge");
}

// E1(z) ~ (e^{-z} / z) sum_k (-1)^k k! / z^k (A&S 5.1.51), for |z| >= 40, truncated at its smallest term.
C asymptotic(C z) {
  C sum = 1.0, term = 1.0;
  for (int k = 1; k < 60; ++k) {
    const C next = term * (-double(k) / z);
    if (std::abs(next) > std::abs(term)) break;
    term = next;
    sum += term;
    if (std::abs(term) < 1e-17) break;
  }
  return std::exp(-z) / z * sum;
}

}  // namespace

std::complex<double> exponential_integral_e1(std::complex<double> z) {
  if (z == C(0.0)) throw std::domain_error("exponential integral E1: z = 0 is a pole");
  const double r = std::abs(z);
  if (r < 2.0) return series(z);
  if (z.real() >= 0.0 || std::abs(z.imag()) >= -z.real()) return continued_fraction(z);
  return r < 40.0 ? series(z) : asymptotic(z);  // within 45 degrees of the negative real axis
}

}  // namespace mrsph::verification::theory
