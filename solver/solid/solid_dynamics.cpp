#include "solid/solid_dynamics.hpp"

#include "core/parallel.hpp"
#include "geometry/particle_normals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrsph {

namespace {

Mat2 deformation_rate(const SolidBody& solid, std::size_t a) {
  const SolidParticles& s = solid.particles;
  const auto list = solid.inner.of(a);
  const Index first = solid.inner.offset(a);
  Mat2 rate = Mat2::Zero();
  for (std::size_t k = 0; k < list.size(); ++k) rate += (s.vel[list[k].j] - s.vel[a]) * solid.weights.w[first + k].transpose();
  return rate;
}

}  // namespace

void initialise_solid(SolidBody& solid) {
  SolidParticles& s = solid.particles;
  DomainBox reference_box;  // the reference configuration is never periodic
  CellGrid grid(reference_box, solid.kernel.cutoff());
  grid.build(s.pos0);
  solid.inner.build(s.pos0, grid, solid.kernel, /*exclude_self=*/true);

  solid.weights = compute_gradient_weights(solid.inner, s.vol0, solid.h(), solid.options.gradient_correction);
  if (solid.options.gradient_correction != GradientCorrection::FirstOrder) {
    // Keep the paper's stability margin: scale the step by omega_max(B0) / omega_max(used).
    const GradientWeights paper = compute_gradient_weights(solid.inner, s.vol0, solid.h(), GradientCorrection::FirstOrder);
    const ElasticMaterial& m = solid.material;
    const Real omega2_paper = highest_frequency_squared(solid.inner, paper.w, paper.w_reverse, paper.w_sum, s.vol0, s.mass,
                                                        s.constrained, m.lambda(), m.shear_modulus());
    const Real omega2_used = highest_frequency_squared(solid.inner, solid.weights.w, solid.weights.w_reverse,
                                                       solid.weights.w_sum, s.vol0, s.mass, s.constrained, m.lambda(),
                                                       m.shear_modulus());
    if (omega2_used > omega2_paper && omega2_paper > 0.0) solid.weights.time_step_scale = std::sqrt(omega2_paper / omega2_used);
  }
  parallel_for_each(s.size(), [&](std::size_t a) {
    s.B[a] = solid.weights.B[a];
    s.F[a] = Mat2::Identity();
    s.dF_dt[a] = Mat2::Zero();
    s.rho[a] = solid.material.density();
    s.stress[a] = Mat2::Zero();
  });
  s.normal0 = normals_from_kernel_gradient(s.vol0, solid.inner);
  s.normal = s.normal0;
}

Real solid_time_step(const SolidBody& solid) {
  const SolidParticles& s = solid.particles;
  const Real h = solid.h();
  const Real c = solid.material.sound_speed();
  // Largest inverse time scale over free particles: max( sqrt(|a|/h), (c + |v|)/h ).
  const Real rate = parallel_max(s.size(), [&](std::size_t a) {
    if (s.constrained[a]) return 0.0;
    return std::max(std::sqrt(s.acc[a].norm() / h), (c + s.vel[a].norm()) / h);
  }, c / h);
  return solid.options.cfl * solid.weights.time_step_scale / rate;
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
Real damping_viscosity(const SolidBody& solid) {
  return solid.options.damping_coefficient * solid.material.density() * solid.material.sound_speed() * solid.h();
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
  const auto list = solid.inner.of(a);
  const Index first = solid.inner.offset(a);
  Vec2 force = s.vol0[a] * (s.stress[a] * solid.weights.w_sum[a]);
  for (std::size_t k = 0; k < list.size(); ++k) force -= s.vol0[list[k].j] * (s.stress[list[k].j] * solid.weights.w_reverse[first + k]);
  return force;
}

void solid_substep(SolidBody& solid, Real dt, const Vec2& body_acceleration) {
  SolidParticles& s = solid.particles;
  const ElasticMaterial& material = solid.material;
  const Real eta = damping_viscosity(solid);

  parallel_for_each(s.size(), [&](std::size_t a) {
    if (!s.constrained[a]) s.pos[a] += 0.5 * dt * s.vel[a];
    s.F[a] += 0.5 * dt * s.dF_dt[a];
    s.rho[a] = material.density() / s.F[a].determinant();
    s.stress[a] = total_stress(solid, s.F[a], s.dF_dt[a], eta);
  });
  parallel_for_each(s.size(), [&](std::size_t a) {
    if (s.constrained[a]) {
      s.vel[a].setZero();
      s.acc[a].setZero();
      s.pos[a] = s.pos0[a];
      return;
    }
    s.acc[a] = (internal_force(solid, a) + s.force_prior[a]) / s.mass[a] + body_acceleration;
    s.vel[a] += dt * s.acc[a];
    s.pos[a] += 0.5 * dt * s.vel[a];
  });
  parallel_for_each(s.size(), [&](std::size_t a) {
    s.dF_dt[a] = deformation_rate(solid, a);
    s.F[a] += 0.5 * dt * s.dF_dt[a];
  });
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
