// The exponential integral E1(z) = int_z^inf e^{-t} / t dt for complex z, principal branch (cut along
// the negative real axis), as the unsteady wake of the plate flutter model needs it (plate_flutter.cpp).
#pragma once

#include <complex>

namespace mrsph::verification::theory {

// Power series for |z| < 2 and within 45 degrees of the negative real axis (A&S 5.1.11, long double),
// continued fraction elsewhere (A&S 5.1.22, modified Lentz), asymptotic series beyond |z| = 40 near
// the negative axis (A&S 5.1.51); relative accuracy about 1e-13.
std::complex<double> exponential_integral_e1(std::complex<double> z);

}  // namespace mrsph::verification::theory
