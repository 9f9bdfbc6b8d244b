#include "boundary/womersley_profile.hpp"

#include <gsl/gsl_complex.h>
#include <gsl/gsl_complex_math.h>

#include <cmath>

namespace mrsph {

Real WomersleyProfile::womersley_number() const {
  return 0.5 * channel_height * std::sqrt(angular_frequency / kinematic_viscosity);
}

Vec2 WomersleyProfile::complex_amplitude(Real y) const {
  const Real half = 0.5 * channel_height;
  const Real y_centre = y - channel_bottom - half;
  const Real kappa = std::sqrt(angular_frequency / (2.0 * kinematic_viscosity));
  const gsl_complex k = gsl_complex_rect(kappa, kappa);
  const gsl_complex ratio = gsl_complex_div(gsl_complex_cosh(gsl_complex_mul_real(k, y_centre)),
                                            gsl_complex_cosh(gsl_complex_mul_real(k, half)));
  const gsl_complex bracket = gsl_complex_sub(gsl_complex_rect(1.0, 0.0), ratio);
  // A / (i rho omega) = -i A / (rho omega)
  const gsl_complex U = gsl_complex_mul(gsl_complex_rect(0.0, -pressure_gradient_amplitude / (density * angular_frequency)), bracket);
  return Vec2(GSL_REAL(U), GSL_IMAG(U));
}

Real WomersleyProfile::velocity(Real y, Real t) const {
  const Vec2 U = complex_amplitude(y);
  // Re{(a + i b)(cos wt + i sin wt)} = a cos wt - b sin wt
  return U.x() * std::cos(angular_frequency * t) - U.y() * std::sin(angular_frequency * t);
}

}  // namespace mrsph
