// The position-based Verlet schedule, with multiple or single time steps (see schedule.hpp).
#pragma once

#include "time/schedule.hpp"

namespace mrsph {

class PositionVerletSchedule final : public Schedule {
 public:
  explicit PositionVerletSchedule(bool single_step, AcousticSteps acoustic_steps = AcousticSteps::EqualSplit)
      : single_step_(single_step), acoustic_steps_(acoustic_steps) {}
  std::string name() const override {
    return single_step_ ? "single_step_position_verlet" : "multi_step_position_verlet";
  }
  Real advance(Simulation& sim, Real max_step) override;

 private:
  Real advance_solids_only(Simulation& sim, Real max_step);
  bool single_step_;
  AcousticSteps acoustic_steps_;
};

// Integrates a solid over [t, t + dt] in sub-steps that respect its criterion and sum to dt
// exactly (paper Eqs. 39-41). Returns the number of sub-steps.
long long integrate_solid_over(SolidBody& solid, const Simulation& sim, Real t, Real dt);
// All the simulation's solids over [t, t + dt]: one by one, or together when some are in contact.
// Returns the sub-steps summed over the bodies.
long long integrate_solids_over(Simulation& sim, Real t, Real dt);

}  // namespace mrsph
