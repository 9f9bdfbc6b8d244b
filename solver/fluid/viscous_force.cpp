#include "fluid/viscous_force.hpp"

#include "core/parallel.hpp"
#include "fluid/viscous_interaction.hpp"
#include "fluid/wall_rules.hpp"
#include "interaction/pair_sweep.hpp"

#include <limits>

namespace mrsph {

namespace {

// FluidContact::fluid_distance and fluid_wall_normal: each fluid particle's height above the surface
// and the surface's normal, from the boundary particle nearest to it among those with a normal
// (wall_rules.hpp; no such particle: the floor and a zero normal).
struct NearestWallDistance {
  struct Nearest {
    Real r;         // to the nearest boundary particle so far
    Real distance;  // the height it gives
    Vec2 normal;    // that particle's
  };
  const BoundaryView& boundary;
  RealArray& distance;
  Vec2Array& normals;
  Real floor;

  Nearest begin(std::size_t) const { return {std::numeric_limits<Real>::infinity(), floor, Vec2::Zero()}; }
  void pair(Nearest& nearest, std::size_t, Index, const Neighbor& n) const {
    const Vec2& normal = (*boundary.normal)[n.j];
    if (normal == Vec2::Zero() || n.r >= nearest.r) return;
    nearest = {n.r, wall_distance_from_nearest(n.r, n.e, normal, (*boundary.depth)[n.j], floor), normal};
  }
  void finish(std::size_t i, const Nearest& nearest) const {
    distance[i] = nearest.distance;
    normals[i] = nearest.normal;
  }
};

void measure_wall_distances(const FluidBody& fluid, std::vector<FluidContact>& contacts) {
  const Real floor = 0.25 * fluid.dp;  // wall_rules.hpp
  for (FluidContact& c : contacts) {
    c.fluid_distance.resize(fluid.particles.size());
    c.fluid_wall_normal.resize(fluid.particles.size());
    sweep_pairs(c.pairs, NearestWallDistance{c.boundary, c.fluid_distance, c.fluid_wall_normal, floor});
  }
}

}  // namespace

std::optional<ViscousInteraction> prepare_viscous_interaction(FluidBody& fluid, std::vector<FluidContact>& contacts,
                                                              const Vec2& body_acceleration) {
  FluidParticles& f = fluid.particles;
  const Real correction = fluid.options.viscous_lattice_correction ? 1.0 / fluid.lattice_laplacian : 1.0;
  const Real mu = fluid.material.viscosity * correction;
  for (FluidContact& c : contacts) c.pair_viscous_force.assign(c.pairs.pair_count(), Vec2::Zero());
  if (mu == 0.0) {
    std::fill(f.force_prior.begin(), f.force_prior.end(), Vec2::Zero());
    return std::nullopt;
  }
  const ViscousWallVelocity rule = fluid.options.viscous_wall_velocity;
  if (rule != ViscousWallVelocity::Mirrored) measure_wall_distances(fluid, contacts);
  const Real nu = fluid.material.viscosity / fluid.material.eos.rho0;
  return ViscousInteraction{f, contacts, mu, fluid.viscous_regularisation(), rule, nu, body_acceleration};
}

void compute_viscous_force(FluidBody& fluid, const NeighborList& inner, std::vector<FluidContact>& contacts,
                           const Vec2& body_acceleration) {
  if (std::optional<ViscousInteraction> viscous = prepare_viscous_interaction(fluid, contacts, body_acceleration))
    sweep_with_contacts(inner, contacts, *viscous);
}

}  // namespace mrsph
