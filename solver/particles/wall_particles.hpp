// Struct-of-arrays state of a rigid wall body (dummy particles after Adami et al. 2012). A wall
// never moves here; its velocity and acceleration seen by the fluid are zero.
#pragma once

#include "core/types.hpp"

namespace mrsph {

struct WallParticles {
  Vec2Array pos;
  Vec2Array normal;   // outward unit normal of the wall body at the particle (into the fluid)
  RealArray vol;      // volume
  RealArray depth;    // distance below the wall's surface, for the viscous wall rule (geometry/particle_normals.hpp)
  Vec2Array vel_ave;  // zero: kept so fluid-boundary code treats walls and solids alike
  Vec2Array acc_ave;  // zero

  std::size_t size() const { return pos.size(); }
  void resize(std::size_t n) {
    pos.resize(n, Vec2::Zero()); normal.resize(n, Vec2::Zero()); vol.resize(n, 0.0); depth.resize(n, 0.0);
    vel_ave.resize(n, Vec2::Zero()); acc_ave.resize(n, Vec2::Zero());
  }
};

}  // namespace mrsph
