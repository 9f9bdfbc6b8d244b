#include "solid/solid_dynamics.hpp"

#include "core/parallel.hpp"
#include "geometry/particle_normals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrsph {

namespace {

// (M^T M + eps I)^-1 M^T: the inverse for a well-conditioned M, bounded for a degenerate one
// (a particle with too few neighbours), as the paper's code does.
Mat2 regularised_inverse(const Mat2& M) {
  return (M.transpose() * M + 1e-8 * Mat2::Identity()).inverse() * M.transpose();
}

Mat2 velocity_gradient_sum(const SolidParticles& s, const NeighborList& inner, std::size_t a) {
  Mat2 sum = Mat2::Zero();
  for (const Neighbor& n : inner.of(a)) sum += (s.vol0[n.j] * n.dW) * (s.vel[n.j] - s.vel[a]) * n.e.transpose();
  return sum;
}

}  // namespace

void initialise_solid(SolidBody& solid) {
  SolidParticles& s = solid.particles;
  DomainBox reference_box;  // the reference configuration is never periodic
  CellGrid grid(reference_box, solid.kernel.cutoff());
  grid.build(s.pos0);
  solid.inner.build(s.pos0, grid, solid.kernel, /*exclude_self=*/true);

  parallel_for_each(s.size(), [&](std::size_t a) {
    Mat2 M = Mat2::Zero();
    for (const Neighbor& n : solid.inner.of(a)) M += (s.vol0[n.j] * n.dW) * (-n.r * n.e) * n.e.transpose();
    s.B[a] = regularised_inverse(M);
    s.F[a] = Mat2::Identity();
    s.dF_dt[a] = Mat2::Zero();
    s.rho[a] = solid.material.density();
    s.stress_PBt[a] = Mat2::Zero();
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
  return solid.options.cfl / rate;
}

void compute_deformation_rate(SolidBody& solid) {
  SolidParticles& s = solid.particles;
  parallel_for_each(s.size(), [&](std::size_t a) { s.dF_dt[a] = velocity_gradient_sum(s, solid.inner, a) * s.B[a]; });
}

void compute_stress(SolidBody& solid) {
  SolidParticles& s = solid.particles;
  parallel_for_each(s.size(), [&](std::size_t a) {
    s.rho[a] = solid.material.density() / s.F[a].determinant();
    s.stress_PBt[a] = solid.material.first_piola_kirchhoff(s.F[a]) * s.B[a].transpose();
  });
}

Vec2 internal_force(const SolidBody& solid, std::size_t a) {
  const SolidParticles& s = solid.particles;
  Vec2 force = Vec2::Zero();
  for (const Neighbor& n : solid.inner.of(a)) force += (s.vol0[n.j] * n.dW) * ((s.stress_PBt[a] + s.stress_PBt[n.j]) * n.e);
  return s.vol0[a] * force;
}

void solid_substep(SolidBody& solid, Real dt, const Vec2& body_acceleration) {
  SolidParticles& s = solid.particles;
  const ElasticMaterial& material = solid.material;

  parallel_for_each(s.size(), [&](std::size_t a) {
    if (!s.constrained[a]) s.pos[a] += 0.5 * dt * s.vel[a];
    s.F[a] += 0.5 * dt * s.dF_dt[a];
    s.rho[a] = material.density() / s.F[a].determinant();
    s.stress_PBt[a] = material.first_piola_kirchhoff(s.F[a]) * s.B[a].transpose();
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
    s.dF_dt[a] = velocity_gradient_sum(s, solid.inner, a) * s.B[a];
    s.F[a] += 0.5 * dt * s.dF_dt[a];
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
