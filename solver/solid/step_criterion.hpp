// The solid's time-step criterion (the paper's Eq. 34) with the contacts' stiffness.
//
// Rate of a free particle: max(sqrt(|a|/h), (c + |v|)/h), the second combined with the particle's
// contact frequency omega_c (solid_contact.cpp) as stiffnesses add, sqrt(((c + |v|)/h)^2 + (scale
// omega_c / 2)^2): a contact alone gives dt <= 2 cfl / omega_c, omega_c dt <= 1.2 at cfl 0.6 (position
// Verlet is stable below 2). The acceleration term alone does not hold a hard contact: blocks meeting
// at Mach 0.1 each lost 8 % of their energy at the paper's B0 step. The step is cfl scale / max(rate,
// c/h), scale the gradient weights' (gradient_weights.hpp).
//
// A body's rate is the maximum over its particles. Both terms out of contact are non-decreasing in
// |a|^2 and |v|^2, and correctly rounded roots and divisions keep that order, so the maximum follows
// exactly from the maxima of |a|^2 and |v|^2: a loop gathers those (RateTerms) and takes the roots
// once (in the gate the roots per particle were 11-15 % of the run).
#pragma once

#include "solid/solid_body.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace mrsph {

// {|a|^2, |v|^2, the rate of a particle in contact}; a clamped particle gives none of them (kNoRate).
using RateTerms = std::array<double, 3>;
inline constexpr double kNoRate = -1.0;

// The Kelvin-Voigt damping's bound on the step: its largest decay rate (GradientWeights::
// highest_damping_rate) times dt at most this. The paper's Eq. 34 has no damping term. Measured on
// the elastic gate with the second-order weights at the criterion's step (omega_max dt = 1.35): rate
// dt = 1.09 ran, 1.31 blew up within 0.02 s without being stopped (reports/antoci.md); 0.75 keeps the
// margin Eq. 34 keeps below omega dt = 2, and leaves the step of every shipped scene as it was.
inline constexpr double kDampingStepLimit = 0.75;

inline RateTerms rate_terms(const SolidBody& solid, std::size_t a) {
  const SolidParticles& s = solid.particles;
  if (s.constrained[a]) return {kNoRate, kNoRate, kNoRate};
  RateTerms t{s.acc[a].squaredNorm(), s.vel[a].squaredNorm(), kNoRate};
  if (s.contact_stiffness[a] != 0.0) {
    const Real acoustic = (solid.material.sound_speed() + std::sqrt(t[1])) / solid.h();
    const Real contact = 0.5 * solid.weights.time_step_scale * std::sqrt(s.contact_stiffness[a] / s.mass[a]);
    t[2] = std::sqrt(acoustic * acoustic + contact * contact);
  }
  return t;
}

// The rate of the particles whose terms (or the maxima of whose terms) are t; 0 for none.
inline Real rate_from_terms(const SolidBody& solid, const RateTerms& t) {
  const Real acceleration = t[0] >= 0.0 ? std::sqrt(std::sqrt(t[0]) / solid.h()) : 0.0;
  const Real acoustic = t[1] >= 0.0 ? (solid.material.sound_speed() + std::sqrt(t[1])) / solid.h() : 0.0;
  return std::max({acceleration, acoustic, t[2], 0.0});
}

inline Real particle_rate(const SolidBody& solid, std::size_t a) { return rate_from_terms(solid, rate_terms(solid, a)); }

inline Real criterion_from_rate(const SolidBody& solid, Real rate) {
  const Real step = solid.options.cfl * solid.weights.time_step_scale / std::max(rate, solid.material.sound_speed() / solid.h());
  const Real damping_rate = solid.weights.highest_damping_rate;
  return damping_rate > 0.0 ? std::min(step, kDampingStepLimit / damping_rate) : step;
}

}  // namespace mrsph
