// How far a run strays from the weakly-compressible regime it assumes (an artificial sound speed
// of ten times the fastest flow keeps the Mach number near 0.1 and |rho / rho0 - 1| ~ M^2 near 1 %;
// Monaghan 1994, "Simulating free surface flows with SPH"): the largest density deviation
// |rho / rho0 - 1| and the largest Mach number |v| / c0 reached by any fluid particle, each with
// when and where, checked at the end of every advection step. A value far above those (a void
// opening at a periodic seam, a jet through a narrow gap) says the run left the regime there, even
// if it did not diverge.
#pragma once

#include "simulation/simulation.hpp"

namespace mrsph {

struct FluidExtreme {
  Real value = 0.0;
  Real time = 0.0;
  Vec2 position = Vec2::Zero();
};

struct CompressibilityRecord {
  FluidExtreme density_deviation;  // |rho / rho0 - 1|
  FluidExtreme mach;               // |v| / c0
};

// Raises the record's extremes to the current fluid state's where it exceeds them (no fluid: no-op).
void update_compressibility_record(const Simulation& sim, CompressibilityRecord& record);

}  // namespace mrsph
