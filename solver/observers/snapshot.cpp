#include "observers/snapshot.hpp"

#include "core/parallel.hpp"
#include "interaction/pair_sweep.hpp"

#include <cmath>

namespace mrsph {

RealArray fluid_vorticity(const Simulation& sim) {
  const FluidParticles& f = sim.fluid().particles;
  const NeighborList& inner = sim.fluid_inner();
  RealArray omega(f.size(), 0.0);
  if (inner.size() != f.size()) return omega;
  parallel_for_each(f.size(), [&](std::size_t i) {
    Real sum = 0.0;
    for_each_pair(inner, i, [&](Index, const Neighbor& n) {
      const Vec2 dv = f.vel[n.j] - f.vel[i];
      const Vec2 grad = n.dW * n.e;
      sum += f.vol[n.j] * (dv.x() * grad.y() - dv.y() * grad.x());
    });
    omega[i] = sum;
  });
  return omega;
}

Real von_mises_stress(const ElasticMaterial& material, const Mat2& F) {
  const Real J = F.determinant();
  const Mat2 S = material.second_piola_kirchhoff(F);
  const Mat2 sigma = F * S * F.transpose() / J;
  const Real S_zz = material.out_of_plane_stress(F);  // plane strain: F_zz = 1, sigma_zz = S_zz / J
  const Real sxx = sigma(0, 0), syy = sigma(1, 1), sxy = sigma(0, 1), szz = S_zz / J;
  return std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
                   3.0 * sxy * sxy);
}

PointCloud fluid_snapshot(const Simulation& sim) {
  const FluidParticles& f = sim.fluid().particles;
  PointCloud cloud;
  cloud.points = f.pos;
  cloud.add_vector("velocity", f.vel);
  cloud.add_scalar("pressure", f.p);
  cloud.add_scalar("density", f.rho);
  cloud.add_scalar("vorticity", fluid_vorticity(sim));
  if (!sim.open_boundaries.empty()) {  // 0: the domain; k: the buffer of open boundary k - 1
    cloud.add_scalar("zone", RealArray(f.zone.begin(), f.zone.end()));
  }
  return cloud;
}

PointCloud wall_snapshot(const WallBody& wall) {
  PointCloud cloud;
  cloud.points = wall.particles.pos;
  cloud.add_vector("normal", wall.particles.normal);
  cloud.add_scalar("volume", wall.particles.vol);
  return cloud;
}

PointCloud solid_snapshot(const SolidBody& solid) {
  const SolidParticles& s = solid.particles;
  PointCloud cloud;
  cloud.points = s.pos;
  cloud.add_vector("velocity", s.vel);
  Vec2Array displacement(s.size());
  RealArray J(s.size()), von_mises(s.size()), constrained(s.size());
  for (std::size_t a = 0; a < s.size(); ++a) {
    displacement[a] = s.pos[a] - s.pos0[a];
    J[a] = s.F[a].determinant();
    von_mises[a] = von_mises_stress(solid.material, s.F[a]);
    constrained[a] = s.constrained[a];
  }
  cloud.add_vector("displacement", displacement);
  cloud.add_scalar("density", s.rho);
  cloud.add_scalar("J", J);
  cloud.add_scalar("von_mises", von_mises);
  cloud.add_scalar("constrained", constrained);
  cloud.add_vector("normal", s.normal);
  cloud.add_vector("velocity_seen_by_fluid", s.vel_ave);
  cloud.add_vector("acceleration_seen_by_fluid", s.acc_ave);
  cloud.add_vector("force_from_fluid", s.force_prior);
  return cloud;
}

}  // namespace mrsph
