#include "fluid/viscous_force.hpp"

#include "core/parallel.hpp"
#include "fluid/viscous_interaction.hpp"
#include "fluid/wall_rules.hpp"
#include "interaction/pair_sweep.hpp"

#include <limits>

namespace mrsph {

namespace {

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

std::optional<ViscousInteraction> prepare_viscous_interaction(FluidBody& fluid, std::vector<FluidContact>& contacts) {
  FluidParticles& f = fluid.particles;
  const Real correction = fluid.options.viscous_lattice_correction ? 1.0 / fluid.lattice_laplacian : 1.0;
  const Real mu = fluid.material.viscosity * correction;
  for (FluidContact& c : contacts) c.pair_viscous_force.assign(c.pairs.pair_count(), Vec2::Zero());
  if (mu == 0.0) {
    std::fill(f.force_prior.begin(), f.force_prior.end(), Vec2::Zero());
    return std::nullopt;
  }
  const bool mirrored = fluid.options.mirrored_wall_velocity;
  if (!mirrored) measure_wall_distances(fluid, contacts);
  return ViscousInteraction{f, contacts, mu, fluid.viscous_regularisation(), mirrored};
}

void compute_viscous_force(FluidBody& fluid, const NeighborList& inner, std::vector<FluidContact>& contacts) {
  if (std::optional<ViscousInteraction> viscous = prepare_viscous_interaction(fluid, contacts))
    sweep_with_contacts(inner, contacts, *viscous);
}

}  // namespace mrsph
