// Velocity-based Verlet with multiple solid time steps: the variant the paper (section 3.3, its
// Fig. 1) contrasts with the position-based scheme. Kept to demonstrate and measure its
// momentum drift; not for production runs.
//
// Per acoustic step dt (fluid kick-drift-kick):
//   v += dt/2 a^n; r += dt v; rho += dt drho/dt(v^{n+1/2}); p = EoS(rho);
//   solid: kappa velocity-Verlet sub-steps with the fluid force of t^n held constant;
//   new forces f^{n+1} (and the solid's force for the next step); v += dt/2 a^{n+1}.
// The fluid receives dt/2 (f^n + f^{n+1}) from each pair, the solid dt f^n: with time steps that
// change from step to step the two no longer cancel.
#pragma once

#include "time/schedule.hpp"

namespace mrsph {

class VelocityVerletSchedule final : public Schedule {
 public:
  std::string name() const override { return "multi_step_velocity_verlet"; }
  Real advance(Simulation& sim, Real max_step) override;

 private:
};

}  // namespace mrsph
