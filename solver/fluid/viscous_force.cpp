#include "fluid/viscous_force.hpp"

#include "core/parallel.hpp"
#include "fluid/wall_rules.hpp"
#include "interaction/pair_sweep.hpp"

namespace mrsph {

namespace {

// F^prior_i = 2 mu V_i sum_j V_j (v_i - v_j) dW_ij / (r_ij + 0.01 h), and the boundary pairs with the
// wall's velocity rule (viscous_force.hpp).
struct ViscousInteraction {
  struct Side {
    const RealArray& vol;
    const Vec2Array& vbar;
    Vec2Array& pair_force;
  };

  FluidParticles& f;
  std::vector<FluidContact>& contacts;
  Real mu, regularisation;

  Vec2 begin(std::size_t) const { return Vec2::Zero(); }
  void inner(Vec2& sum, std::size_t i, const Neighbor& n) const {
    sum += f.vol[n.j] * (f.vel[i] - f.vel[n.j]) * (n.dW / (n.r + regularisation));
  }
  void after_inner(std::size_t i, Vec2& sum) const { sum = 2.0 * mu * f.vol[i] * sum; }
  Side boundary(std::size_t c) const {
    return {*contacts[c].boundary.vol, *contacts[c].boundary.vel_ave, contacts[c].pair_viscous_force};
  }
  void contact(Vec2& force, std::size_t i, const Side& b, Index k, const Neighbor& n) const {
    const Vec2 pair = 2.0 * mu * f.vol[i] * b.vol[n.j] * wall_velocity_difference(f.vel[i], b.vbar[n.j]) *
                      (n.dW / (n.r + regularisation));
    b.pair_force[k] = pair;
    force += pair;
  }
  void finish(std::size_t i, const Vec2& force) const { f.force_prior[i] = force; }
};

}  // namespace

void compute_viscous_force(FluidBody& fluid, const NeighborList& inner, std::vector<FluidContact>& contacts) {
  FluidParticles& f = fluid.particles;
  const Real correction = fluid.options.viscous_lattice_correction ? 1.0 / fluid.lattice_laplacian : 1.0;
  const Real mu = fluid.material.viscosity * correction;
  for (FluidContact& c : contacts) c.pair_viscous_force.assign(c.pairs.pair_count(), Vec2::Zero());
  if (mu == 0.0) {
    std::fill(f.force_prior.begin(), f.force_prior.end(), Vec2::Zero());
    return;
  }
  sweep_with_contacts(inner, contacts, ViscousInteraction{f, contacts, mu, fluid.viscous_regularisation()});
}

}  // namespace mrsph
