#include "fluid/viscous_force.hpp"

#include "core/parallel.hpp"
#include "fluid/wall_rules.hpp"
#include "interaction/pair_sweep.hpp"

#include <limits>

namespace mrsph {

namespace {

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

// FluidContact::fluid_distance: each fluid particle's height above the surface, from the boundary
// particle nearest to it among those with a normal (wall_rules.hpp).
struct NearestWallDistance {
  struct Nearest {
    Real r;         // to the nearest boundary particle so far
    Real distance;  // the height it gives
  };
  const BoundaryView& boundary;
  RealArray& distance;
  Real floor;

  Nearest begin(std::size_t) const { return {std::numeric_limits<Real>::infinity(), floor}; }
  void pair(Nearest& nearest, std::size_t, Index, const Neighbor& n) const {
    const Vec2& normal = (*boundary.normal)[n.j];
    if (normal == Vec2::Zero() || n.r >= nearest.r) return;
    nearest = {n.r, wall_distance_from_nearest(n.r, n.e, normal, (*boundary.depth)[n.j], floor)};
  }
  void finish(std::size_t i, const Nearest& nearest) const { distance[i] = nearest.distance; }
};

void measure_wall_distances(const FluidBody& fluid, std::vector<FluidContact>& contacts) {
  const Real floor = 0.25 * fluid.dp;  // wall_rules.hpp
  for (FluidContact& c : contacts) {
    c.fluid_distance.resize(fluid.particles.size());
    sweep_pairs(c.pairs, NearestWallDistance{c.boundary, c.fluid_distance, floor});
  }
}

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
  const bool mirrored = fluid.options.mirrored_wall_velocity;
  if (!mirrored) measure_wall_distances(fluid, contacts);
  sweep_with_contacts(inner, contacts, ViscousInteraction{f, contacts, mu, fluid.viscous_regularisation(), mirrored});
}

}  // namespace mrsph
