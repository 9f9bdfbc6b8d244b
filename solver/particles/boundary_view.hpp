// What the fluid needs to know of a boundary particle set (rigid wall or elastic solid) to impose
// the wall condition of Adami et al. (2012): volume, normal, and the velocity and acceleration the
// fluid sees (time-averaged over the acoustic step for an elastic solid, paper Eq. 35); each
// particle's depth below the body's surface (the viscous wall rule, wall_rules.hpp); and, for a
// boundary that moves, its positions (null for a wall, which never moves).
#pragma once

#include "core/types.hpp"

namespace mrsph {

struct BoundaryView {
  const RealArray* vol = nullptr;
  const Vec2Array* normal = nullptr;
  const Vec2Array* vel_ave = nullptr;
  const Vec2Array* acc_ave = nullptr;
  const Vec2Array* pos = nullptr;
  const RealArray* depth = nullptr;
};

}  // namespace mrsph
