// Struct-of-arrays state of a weakly-compressible fluid body.
#pragma once

#include "core/types.hpp"

#include <vector>

namespace mrsph {

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

  std::size_t size() const { return pos.size(); }
  void resize(std::size_t n) {
    pos.resize(n, Vec2::Zero()); vel.resize(n, Vec2::Zero());
    rho.resize(n, 0.0); p.resize(n, 0.0); mass.resize(n, 0.0); vol.resize(n, 0.0); drho_dt.resize(n, 0.0);
    pressure_force.resize(n, Vec2::Zero()); dissipation_force.resize(n, Vec2::Zero());
    force_prior.resize(n, Vec2::Zero());
  }
  // Reorders every field: new particle k is old particle order[k].
  void permute(const std::vector<Index>& order);
};

}  // namespace mrsph
