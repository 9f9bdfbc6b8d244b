// Struct-of-arrays state of a weakly-compressible fluid body.
#pragma once

#include "core/types.hpp"

#include <cstdint>
#include <vector>

namespace mrsph {

// Where a fluid particle is: in the computational domain, or in the buffer of open boundary k
// (boundary/open_boundary.hpp), stored as k + 1. Buffer particles are neighbours of the domain's
// particles but their state is imposed, not integrated.
using ZoneArray = std::vector<std::uint8_t>;
inline constexpr std::uint8_t kDomainZone = 0;

struct FluidParticles {
  Vec2Array pos;                // position
  Vec2Array vel;                // velocity
  RealArray rho;                // density
  RealArray p;                  // pressure (from the equation of state)
  RealArray mass;               // mass, constant
  RealArray vol;                // volume m / rho
  RealArray drho_dt;            // density rate, kept between the two halves of the Verlet step
  Vec2Array pressure_force;     // f^p: pressure (and wall Riemann) force of the current acoustic step
  Vec2Array dissipation_force;  // f^d: Riemann momentum dissipation, from the previous 2nd half
  Vec2Array force_prior;        // F^prior: viscous force, held over the acoustic steps of an advection step
  ZoneArray zone;               // kDomainZone, or 1 + the index of the open boundary whose buffer holds it

  // The one list of fields: resize, permute, append, erase and the checkpoint all go through it.
  // Particles is FluidParticles or const FluidParticles; visit(array, name) for each field.
  template <class Particles, class Visit>
  static void for_each_field(Particles& f, Visit&& visit) {
    visit(f.pos, "fluid positions"); visit(f.vel, "fluid velocities"); visit(f.rho, "fluid densities");
    visit(f.p, "fluid pressures"); visit(f.mass, "fluid masses"); visit(f.vol, "fluid volumes");
    visit(f.drho_dt, "fluid density rates"); visit(f.pressure_force, "fluid pressure forces");
    visit(f.dissipation_force, "fluid dissipation forces"); visit(f.force_prior, "fluid prior forces");
    visit(f.zone, "fluid zones");
  }

  std::size_t size() const { return pos.size(); }
  bool in_domain(std::size_t i) const { return zone[i] == kDomainZone; }
  // New entries are zero (in the domain).
  void resize(std::size_t n);
  // Reorders every field: new particle k is old particle order[k].
  void permute(const std::vector<Index>& order);
  // Appends a copy of particle i (every field).
  void append_copy_of(std::size_t i);
  // Removes the particles whose flag is set, keeping the others in their order.
  void erase(const std::vector<bool>& remove);
};

}  // namespace mrsph
