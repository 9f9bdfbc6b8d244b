#include "fluid/viscous_force.hpp"

#include "core/parallel.hpp"

namespace mrsph {

void compute_viscous_force(FluidBody& fluid, const NeighborList& inner, std::vector<FluidContact>& contacts) {
  FluidParticles& f = fluid.particles;
  const Real correction = fluid.options.viscous_lattice_correction ? 1.0 / fluid.lattice_laplacian : 1.0;
  const Real mu = fluid.material.viscosity * correction;
  const Real regularisation = fluid.viscous_regularisation();
  for (FluidContact& c : contacts) c.pair_viscous_force.assign(c.pairs.pair_count(), Vec2::Zero());
  if (mu == 0.0) {
    std::fill(f.force_prior.begin(), f.force_prior.end(), Vec2::Zero());
    return;
  }
  parallel_for_each(f.size(), [&](std::size_t i) {
    Vec2 sum = Vec2::Zero();
    for (const Neighbor& n : inner.of(i))
      sum += f.vol[n.j] * (f.vel[i] - f.vel[n.j]) * (n.dW / (n.r + regularisation));
    Vec2 force = 2.0 * mu * f.vol[i] * sum;
    for (FluidContact& c : contacts) {
      const RealArray& vol = *c.boundary.vol;
      const Vec2Array& vbar = *c.boundary.vel_ave;
      const Index first = c.pairs.offset(i);
      const auto list = c.pairs.of(i);
      for (std::size_t k = 0; k < list.size(); ++k) {
        const Neighbor& n = list[k];
        const Vec2 pair = 2.0 * mu * f.vol[i] * vol[n.j] * 2.0 * (f.vel[i] - vbar[n.j]) * (n.dW / (n.r + regularisation));
        c.pair_viscous_force[first + k] = pair;
        force += pair;
      }
    }
    f.force_prior[i] = force;
  });
}

}  // namespace mrsph
