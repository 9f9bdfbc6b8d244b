#include "solid/solid_dynamics.hpp"

#include "core/loop_team.hpp"
#include "core/parallel.hpp"
#include "geometry/particle_normals.hpp"
#include "interaction/pair_sweep.hpp"
#include "solid/solid_contact.hpp"
#include "solid/step_criterion.hpp"
#include "core/step_splitting.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrsph {

namespace {

// Particles per chunk of a solid loop (core/loop_team.hpp): a few hundred nanoseconds of work per
// particle, so a claim (one compare-and-swap) is a small part of a chunk.
constexpr std::size_t kSolidChunk = 64;

Mat2 deformation_rate(const SolidBody& solid, std::size_t a) {
  const SolidParticles& s = solid.particles;
  const GradientWeights& g = solid.weights;
  return weighted_gradient(solid.inner, g.neighbor, g.w, s.vel, a);
}

// The Kelvin-Voigt viscosity eta = coefficient rho0 c_S h (SolidOptions::damping_coefficient).
Real damping_viscosity(const SolidBody& solid) {
  return solid.options.damping_coefficient * solid.material.density() * solid.material.sound_speed() * solid.h();
}

// The weights a body gets. A body in contact keeps the quadratic fits at its corners, and with them
// the step they set: its bulk modes then run at omega dt = 1.15 instead of 1.35 (gradient_weights.hpp),
// and an impact needs that margin. Two blocks meeting at relative Mach 0.2 (tests/test_solid_contact.cpp)
// kept their energy to 0.12 % with it, lost 3.9 % without it, 2.4 % with the paper's B0 at its step
// (reports/performance.md section 12).
GradientCorrection correction_in_use(const SolidBody& solid) {
  if (solid.in_contact && solid.options.gradient_correction == GradientCorrection::SecondOrder)
    return GradientCorrection::SecondOrderWithCorners;
  return solid.options.gradient_correction;
}

}  // namespace

void initialise_solid(SolidBody& solid) {
  SolidParticles& s = solid.particles;
  DomainBox reference_box;  // the reference configuration is never periodic
  CellGrid grid(reference_box, solid.kernel.cutoff());
  grid.build(s.pos0);
  solid.inner.build(s.pos0, grid, solid.kernel, /*exclude_self=*/true);

  const GradientCorrection correction = correction_in_use(solid);
  solid.weights = compute_gradient_weights(solid.inner, s.vol0, solid.h(), correction);
  if (correction != GradientCorrection::FirstOrder)
    calibrate_time_step(solid.weights, solid.inner, s.vol0, s.mass, s.constrained, solid.h(), solid.material.lambda(),
                        solid.material.shear_modulus());
  if (const Real eta = damping_viscosity(solid); eta > 0.0)
    solid.weights.highest_damping_rate = highest_frequency_squared(solid.inner, solid.weights.w, solid.weights.w_reverse,
                                                                   solid.weights.w_sum, s.vol0, s.mass, s.constrained,
                                                                   0.0, 0.5 * eta);
  parallel_for_each(s.size(), [&](std::size_t a) {
    s.B[a] = solid.weights.B[a];
    s.F[a] = Mat2::Identity();
    s.dF_dt[a] = Mat2::Zero();
    s.rho[a] = solid.material.density();
    s.stress[a] = Mat2::Zero();
  });
  s.normal0 = normals_from_kernel_gradient(s.vol0, solid.inner);
  s.depth0 = depths_below_surface(s.normal0, solid.inner, solid.dp, solid.kernel.cutoff());
  s.normal = s.normal0;
  solid.external_force.assign(s.size(), Vec2::Zero());
  solid.active.clear();
  for (std::size_t a = 0; a < s.size(); ++a) {
    bool needed = !s.constrained[a];
    for_each_pair(solid.inner, a, [&](Index, const Neighbor& n) { needed = needed || !s.constrained[n.j]; });
    if (needed) solid.active.push_back(static_cast<Index>(a));
  }
}

Real solid_time_step(const SolidBody& solid) {
  const SolidParticles& s = solid.particles;
  return criterion_from_rate(
      solid, parallel_max(s.size(), [&](std::size_t a) { return particle_rate(solid, a); }, 0.0, kGrainSolidLoop));
}

void compute_deformation_rate(SolidBody& solid) {
  SolidParticles& s = solid.particles;
  parallel_for_each(s.size(), [&](std::size_t a) { s.dF_dt[a] = deformation_rate(solid, a); });
}

namespace {
// First Piola-Kirchhoff stress, elastic plus the optional Kelvin-Voigt part F eta dE/dt.
Mat2 total_stress(const SolidBody& solid, const Mat2& F, const Mat2& dF_dt, Real eta) {
  Mat2 P = solid.material.first_piola_kirchhoff(F);
  if (eta > 0.0) {
    const Mat2 rate = F.transpose() * dF_dt;
    P += F * (eta * 0.5 * (rate + rate.transpose()));
  }
  return P;
}
}  // namespace

void compute_stress(SolidBody& solid) {
  SolidParticles& s = solid.particles;
  const Real eta = damping_viscosity(solid);
  parallel_for_each(s.size(), [&](std::size_t a) {
    s.rho[a] = solid.material.density() / s.F[a].determinant();
    s.stress[a] = total_stress(solid, s.F[a], s.dF_dt[a], eta);
  });
}

Vec2 internal_force(const SolidBody& solid, std::size_t a) {
  const SolidParticles& s = solid.particles;
  const GradientWeights& g = solid.weights;
  return variational_force(solid.inner, g.neighbor, g.w_reverse, g.w_sum[a], s.vol0, s.stress, a);
}

namespace {

// r += h v (free particles); F += h dF/dt; rho and P from F.
void half_step(LoopTeam& team, SolidBody& solid, Real h, Real eta) {
  SolidParticles& s = solid.particles;
  team.for_each(solid.active.size(), kSolidChunk, [&](std::size_t k) {
    const Index a = solid.active[k];
    if (!s.constrained[a]) s.pos[a] += h * s.vel[a];
    s.F[a] += h * s.dF_dt[a];
    s.rho[a] = solid.material.density() / s.F[a].determinant();
    s.stress[a] = total_stress(solid, s.F[a], s.dF_dt[a], eta);
  });
}

// Tether forces of the current state into solid.external_force.
void apply_tethers(SolidBody& solid) {
  SolidParticles& s = solid.particles;
  for (const Tether& t : solid.tethers) {
    const Vec2 force = tether_force(solid, t);
    Real mass = 0.0;
    for (Index a : t.particles) mass += s.mass[a];
    for (Index a : t.particles) solid.external_force[a] += force * (s.mass[a] / mass);
  }
}

// Replaces the accelerations of the rigid region's particles by the rigid-body motion they produce
// (linear and angular momentum of the region unchanged).
void project_rigid(SolidBody& solid) {
  SolidParticles& s = solid.particles;
  const std::vector<Index>& part = solid.rigid->particles;
  Real M = 0.0;
  Vec2 centre = Vec2::Zero(), velocity = Vec2::Zero(), force = Vec2::Zero();
  for (Index a : part) {
    M += s.mass[a];
    centre += s.mass[a] * s.pos[a];
    velocity += s.mass[a] * s.vel[a];
    force += s.mass[a] * s.acc[a];
  }
  centre /= M;
  Real inertia = 0.0, torque = 0.0, spin = 0.0;
  for (Index a : part) {
    const Vec2 d = s.pos[a] - centre;
    inertia += s.mass[a] * d.squaredNorm();
    torque += s.mass[a] * (d.x() * s.acc[a].y() - d.y() * s.acc[a].x());
    spin += s.mass[a] * (d.x() * s.vel[a].y() - d.y() * s.vel[a].x());
  }
  const Vec2 a_c = force / M;
  const Real alpha = inertia > 0.0 ? torque / inertia : 0.0;
  const Real omega = inertia > 0.0 ? spin / inertia : 0.0;
  for (Index a : part) {
    const Vec2 d = s.pos[a] - centre;
    s.acc[a] = a_c + alpha * Vec2(-d.y(), d.x()) - omega * omega * d;
  }
}

bool uses_external_force(const SolidBody& solid) { return solid.rigid || !solid.tethers.empty() || solid.in_contact; }

// external_force of the current state: tethers here, contacts added by the caller.
void begin_external_forces(SolidBody& solid) {
  if (!uses_external_force(solid)) return;
  std::fill(solid.external_force.begin(), solid.external_force.end(), Vec2::Zero());
  std::fill(solid.particles.contact_stiffness.begin(), solid.particles.contact_stiffness.end(), Real(0));
  apply_tethers(solid);
}

// v += dt a with a = (f + F^prior + external)/m + g; r += dt/2 v. Returns the criterion's rate.
Real momentum_pass(LoopTeam& team, SolidBody& solid, Real dt, const Vec2& g) {
  SolidParticles& s = solid.particles;
  if (uses_external_force(solid)) {
    // Accelerations first, then the constraints (they need all of them), then the update.
    team.for_each(solid.active.size(), kSolidChunk, [&](std::size_t k) {
      const Index a = solid.active[k];
      if (s.constrained[a]) {
        s.acc[a].setZero();
        return;
      }
      s.acc[a] = (internal_force(solid, a) + s.force_prior[a] + solid.external_force[a]) / s.mass[a] + g;
    });
    if (solid.rigid) project_rigid(solid);
    return rate_from_terms(solid, team.max_over_each<3>(solid.active.size(), kSolidChunk, [&](std::size_t k) {
      const Index a = solid.active[k];
      if (s.constrained[a]) {
        s.vel[a].setZero();
        s.pos[a] = s.pos0[a];
        return RateTerms{kNoRate, kNoRate, kNoRate};
      }
      s.vel[a] += dt * s.acc[a];
      s.pos[a] += 0.5 * dt * s.vel[a];
      return rate_terms(solid, a);
    }, kNoRate));
  }
  return rate_from_terms(solid, team.max_over_each<3>(solid.active.size(), kSolidChunk, [&](std::size_t k) {
    const Index a = solid.active[k];
    if (s.constrained[a]) {
      s.vel[a].setZero();
      s.acc[a].setZero();
      s.pos[a] = s.pos0[a];
      return RateTerms{kNoRate, kNoRate, kNoRate};
    }
    s.acc[a] = (internal_force(solid, a) + s.force_prior[a]) / s.mass[a] + g;
    s.vel[a] += dt * s.acc[a];
    s.pos[a] += 0.5 * dt * s.vel[a];
    return rate_terms(solid, a);
  }, kNoRate));
}

// dF/dt from the new velocities; F += h_end dF/dt ends this sub-step. Then the first half of the
// next one (h_next > 0): r += h_next v; F += h_next dF/dt; rho and P.
void deformation_pass(LoopTeam& team, SolidBody& solid, Real h_end, Real h_next, Real eta) {
  SolidParticles& s = solid.particles;
  team.for_each(solid.active.size(), kSolidChunk, [&](std::size_t k) {
    const Index a = solid.active[k];
    s.dF_dt[a] = deformation_rate(solid, a);
    s.F[a] += (h_end + h_next) * s.dF_dt[a];
    if (h_next == 0.0) return;
    if (!s.constrained[a]) s.pos[a] += h_next * s.vel[a];
    s.rho[a] = solid.material.density() / s.F[a].determinant();
    s.stress[a] = total_stress(solid, s.F[a], s.dF_dt[a], eta);
  });
}

// advance_solids with the loops run by `team`.
long long advance_solids_with(LoopTeam& team, std::span<SolidBody> solids, std::span<SolidContact> contacts, Real t,
                              Real dt, const std::function<Vec2(Real)>& body_acceleration) {
  const std::size_t n = solids.size();
  std::vector<Real> eta(n), rate(n);
  for (std::size_t b = 0; b < n; ++b) {
    const SolidBody& solid = solids[b];
    eta[b] = damping_viscosity(solid);
    const auto particle = [&](std::size_t k) { return particle_rate(solid, solid.active[k]); };
    rate[b] = team.max_over(solid.active.size(), kSolidChunk, particle, 0.0);
  }
  // One sub-step for all the bodies, the smallest of their criteria.
  const auto criterion = [&] {
    Real c = std::numeric_limits<Real>::infinity();
    for (std::size_t b = 0; b < n; ++b) c = std::min(c, criterion_from_rate(solids[b], rate[b]));
    return c;
  };
  // A bound on a body's speed from its rate: rate >= (c + |v|) / h.
  const auto speed_bound = [&](std::size_t b) {
    return std::max(Real(0), rate[b] * solids[b].h() - solids[b].material.sound_speed());
  };
  const auto add_travel = [&](Real duration) {
    for (SolidContact& c : contacts)
      c.travel += duration * (speed_bound(c.first) + (c.second_is_wall ? Real(0) : speed_bound(c.second)));
  };
  SplitStep step = split_remaining(dt, criterion());
  for (std::size_t b = 0; b < n; ++b) half_step(team, solids[b], 0.5 * step.size, eta[b]);
  add_travel(0.5 * step.size);
  Real elapsed = 0.0;
  long long count = 0;
  for (;;) {
    const Vec2 g = body_acceleration(t + elapsed + 0.5 * step.size);
    for (SolidBody& solid : solids) begin_external_forces(solid);
    for (SolidContact& c : contacts) apply_contact(c, solids);
    for (std::size_t b = 0; b < n; ++b) rate[b] = momentum_pass(team, solids[b], step.size, g);
    add_travel(0.5 * step.size);
    elapsed += step.size;
    ++count;
    if (step.last) {
      for (std::size_t b = 0; b < n; ++b) deformation_pass(team, solids[b], 0.5 * step.size, 0.0, eta[b]);
      return count * static_cast<long long>(n);
    }
    const SplitStep next = split_remaining(dt - elapsed, criterion());
    for (std::size_t b = 0; b < n; ++b) deformation_pass(team, solids[b], 0.5 * step.size, 0.5 * next.size, eta[b]);
    add_travel(0.5 * next.size);
    step = next;
  }
}

}  // namespace

long long advance_solids(std::span<SolidBody> solids, std::span<SolidContact> contacts, Real t, Real dt,
                         const std::function<Vec2(Real)>& body_acceleration) {
  if (solids.empty()) return 0;
  // A helper for every two chunks: more would spend longer claiming than working. Bodies in contact
  // stay on one thread: their sub-steps are six loops of a few hundred particles with the serial
  // contact search between, and the valve ran 14 % slower with a helper (17.4 s against 15.3 s).
  std::size_t active = 0;
  for (const SolidBody& solid : solids) active += solid.active.size();
  const std::size_t helpers = contacts.empty() ? active / (2 * kSolidChunk) : 0;
  long long count = 0;
  LoopTeam::run(helpers, [&](LoopTeam& team) {
    count = advance_solids_with(team, solids, contacts, t, dt, body_acceleration);
  });
  return count;
}

long long advance_solid(SolidBody& solid, Real t, Real dt, const std::function<Vec2(Real)>& body_acceleration) {
  return advance_solids(std::span<SolidBody>(&solid, 1), {}, t, dt, body_acceleration);
}

void solid_substep_velocity_verlet(SolidBody& solid, Real dt, const Vec2& body_acceleration) {
  SolidParticles& s = solid.particles;
  parallel_for_each(s.size(), [&](std::size_t a) {
    if (s.constrained[a]) return;
    s.vel[a] += 0.5 * dt * s.acc[a];
    s.pos[a] += dt * s.vel[a];
  });
  compute_deformation_rate(solid);
  parallel_for_each(s.size(), [&](std::size_t a) { s.F[a] += dt * s.dF_dt[a]; });
  compute_stress(solid);
  parallel_for_each(s.size(), [&](std::size_t a) {
    if (s.constrained[a]) {
      s.vel[a].setZero();
      s.acc[a].setZero();
      s.pos[a] = s.pos0[a];
      return;
    }
    s.acc[a] = (internal_force(solid, a) + s.force_prior[a]) / s.mass[a] + body_acceleration;
    s.vel[a] += 0.5 * dt * s.acc[a];
  });
}

Vec2 tether_force(const SolidBody& solid, const Tether& t) {
  const SolidParticles& s = solid.particles;
  Real mass = 0.0;
  Vec2 centre = Vec2::Zero(), velocity = Vec2::Zero();
  for (Index a : t.particles) {
    mass += s.mass[a];
    centre += s.mass[a] * s.pos[a];
    velocity += s.mass[a] * s.vel[a];
  }
  centre /= mass;
  velocity /= mass;
  const Vec2 to_anchor = t.anchor - centre;
  const Real length = to_anchor.norm();
  const Real stretch = length - t.rest_length;
  if (stretch <= 0.0 || length == 0.0) return Vec2::Zero();
  const Vec2 direction = to_anchor / length;
  const Real stretch_rate = -velocity.dot(direction);  // d|anchor - r_c|/dt
  const Real tension = std::max(Real(0), t.stiffness * stretch * (1.0 + t.damping * stretch_rate));
  return tension * direction;
}

void update_solid_normals(SolidBody& solid) {
  SolidParticles& s = solid.particles;
  parallel_for_each(s.size(), [&](std::size_t a) {
    const Mat2& F = s.F[a];
    const Real c = F(0, 0) + F(1, 1), d = F(1, 0) - F(0, 1);
    const Real norm = std::sqrt(c * c + d * d);
    if (norm == 0.0) { s.normal[a] = s.normal0[a]; return; }
    Mat2 R;
    R << c, -d, d, c;
    s.normal[a] = R * s.normal0[a] / norm;
  });
}

Real solid_kinetic_energy(const SolidBody& solid) {
  const SolidParticles& s = solid.particles;
  Real e = 0.0;
  for (std::size_t a = 0; a < s.size(); ++a) e += 0.5 * s.mass[a] * s.vel[a].squaredNorm();
  return e;
}

Real solid_strain_energy(const SolidBody& solid) {
  const SolidParticles& s = solid.particles;
  Real e = 0.0;
  for (std::size_t a = 0; a < s.size(); ++a) e += s.vol0[a] * solid.material.strain_energy_density(s.F[a]);
  return e;
}

Vec2 solid_momentum(const SolidBody& solid) {
  const SolidParticles& s = solid.particles;
  Vec2 m = Vec2::Zero();
  for (std::size_t a = 0; a < s.size(); ++a) m += s.mass[a] * s.vel[a];
  return m;
}

}  // namespace mrsph
