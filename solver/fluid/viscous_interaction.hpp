// The viscous force's pair terms (viscous_force.hpp), as an interaction for the pair sweeps, so that
// a schedule may run them beside another term of the same pairs (advection_pair_terms.hpp).
#pragma once

#include "fluid/fluid_body.hpp"
#include "fluid/wall_rules.hpp"

#include <optional>

namespace mrsph {

// F^prior_i = 2 mu V_i sum_j V_j (v_i - v_j) dW_ij / (r_ij + 0.01 h), and the boundary pairs with the
// wall's velocity rule (viscous_force.hpp).
struct ViscousInteraction {
  struct Side {
    const RealArray& vol;
    const Vec2Array& vbar;
    const RealArray& depth;
    const RealArray& fluid_distance;
    Vec2Array& pair_force;
  };

  FluidParticles& f;
  std::vector<FluidContact>& contacts;
  Real mu, regularisation;
  bool mirrored;

  Vec2 begin(std::size_t) const { return Vec2::Zero(); }
  void inner(Vec2& sum, std::size_t i, const Neighbor& n) const {
    sum += f.vol[n.j] * (f.vel[i] - f.vel[n.j]) * (n.dW / (n.r + regularisation));
  }
  void after_inner(std::size_t i, Vec2& sum) const { sum = 2.0 * mu * f.vol[i] * sum; }
  Side boundary(std::size_t c) const {
    FluidContact& contact = contacts[c];
    return {*contact.boundary.vol, *contact.boundary.vel_ave, *contact.boundary.depth, contact.fluid_distance,
            contact.pair_viscous_force};
  }
  void contact(Vec2& force, std::size_t i, const Side& b, Index k, const Neighbor& n) const {
    const Vec2 difference = mirrored ? wall_velocity_difference(f.vel[i], b.vbar[n.j])
                                     : wall_viscous_velocity_difference(f.vel[i], b.vbar[n.j], b.fluid_distance[i], b.depth[n.j]);
    const Vec2 pair = 2.0 * mu * f.vol[i] * b.vol[n.j] * difference * (n.dW / (n.r + regularisation));
    b.pair_force[k] = pair;
    force += pair;
  }
  void finish(std::size_t i, const Vec2& force) const { f.force_prior[i] = force; }
};

// Readies the contacts for the sweep (their pair forces zeroed; the fluid particles' heights above
// the walls measured where the wall rule needs them) and returns the interaction; without viscosity,
// sets F^prior to zero and returns none.
std::optional<ViscousInteraction> prepare_viscous_interaction(FluidBody& fluid, std::vector<FluidContact>& contacts);

}  // namespace mrsph
