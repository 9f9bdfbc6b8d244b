// The viscous force's pair terms (viscous_force.hpp), as an interaction for the pair sweeps, so that
// a schedule may run them beside another term of the same pairs (advection_pair_terms.hpp).
#pragma once

#include "fluid/fluid_body.hpp"
#include "fluid/wall_rules.hpp"

#include <optional>

namespace mrsph {

// F^prior_i = 2 mu V_i sum_j V_j (v_i - v_j) dW_ij / (r_ij + 0.01 h), and the boundary pairs with the
// wall's velocity rule (viscous_force.hpp). The quadratic rule's drive is a^p_i + b - abar_a, with
// a^p_i from the last acoustic step's pressure force and b the body force at the advection step's start.
struct ViscousInteraction {
  struct Side {
    const RealArray& vol;
    const Vec2Array& vbar;
    const RealArray& depth;
    const RealArray& fluid_distance;
    const Vec2Array& fluid_wall_normal;
    const Vec2Array& abar;
    Vec2Array& pair_force;
  };

  FluidParticles& f;
  std::vector<FluidContact>& contacts;
  Real mu, regularisation;
  ViscousWallVelocity rule;
  Real nu;                  // the quadratic rule's kinematic viscosity (without the lattice correction)
  Vec2 body_acceleration;   // b, for the quadratic rule

  Vec2 begin(std::size_t) const { return Vec2::Zero(); }
  void inner(Vec2& sum, std::size_t i, const Neighbor& n) const {
    sum += f.vol[n.j] * (f.vel[i] - f.vel[n.j]) * (n.dW / (n.r + regularisation));
  }
  void after_inner(std::size_t i, Vec2& sum) const { sum = 2.0 * mu * f.vol[i] * sum; }
  Side boundary(std::size_t c) const {
    FluidContact& contact = contacts[c];
    return {*contact.boundary.vol, *contact.boundary.vel_ave, *contact.boundary.depth, contact.fluid_distance,
            contact.fluid_wall_normal, *contact.boundary.acc_ave, contact.pair_viscous_force};
  }
  void contact(Vec2& force, std::size_t i, const Side& b, Index k, const Neighbor& n) const {
    const Vec2 difference = velocity_difference(i, b, n.j);
    const Vec2 pair = 2.0 * mu * f.vol[i] * b.vol[n.j] * difference * (n.dW / (n.r + regularisation));
    b.pair_force[k] = pair;
    force += pair;
  }
  void finish(std::size_t i, const Vec2& force) const { f.force_prior[i] = force; }

  // v_i - v^d_a by the fluid's rule (wall_rules.hpp).
  Vec2 velocity_difference(std::size_t i, const Side& b, Index a) const {
    if (rule == ViscousWallVelocity::Mirrored) return wall_velocity_difference(f.vel[i], b.vbar[a]);
    Vec2 difference = wall_viscous_velocity_difference(f.vel[i], b.vbar[a], b.fluid_distance[i], b.depth[a]);
    if (rule == ViscousWallVelocity::Quadratic && b.fluid_wall_normal[i] != Vec2::Zero()) {
      const Vec2 drive = f.pressure_force[i] / f.mass[i] + body_acceleration - b.abar[a];
      difference += wall_viscous_curvature_difference(wall_profile_curvature(drive, b.fluid_wall_normal[i], nu),
                                                      b.fluid_distance[i], b.depth[a]);
    }
    return difference;
  }
};

// Readies the contacts for the sweep (their pair forces zeroed; the fluid particles' heights above
// the walls, and the walls' normals there, measured where the wall rule needs them) and returns the
// interaction; without viscosity, sets F^prior to zero and returns none. body_acceleration: b at the
// advection step's start (the quadratic rule's drive).
std::optional<ViscousInteraction> prepare_viscous_interaction(FluidBody& fluid, std::vector<FluidContact>& contacts,
                                                              const Vec2& body_acceleration);

}  // namespace mrsph
