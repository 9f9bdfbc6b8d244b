// Time-integration schedules, selected by name in a scene. Each advances a Simulation by one
// advection step (at most `max_step`: the runner passes the time left to the end) and returns its size.
//   multi_step_position_verlet   the paper's method (Algorithm 1): dual-criteria fluid steps, and
//                                kappa solid sub-steps per acoustic step, all position-based Verlet
//   single_step_position_verlet  the same, with one step for both: the acoustic step is the smaller
//                                of the fluid and solid criteria (paper Eq. 26) and kappa = 1
//   multi_step_velocity_verlet   velocity-based Verlet with multiple solid steps: the variant the
//                                paper shows to violate momentum conservation (for comparison)
#pragma once

#include "simulation/simulation.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mrsph {

class Schedule {
 public:
  virtual ~Schedule() = default;
  virtual std::string name() const = 0;
  virtual Real advance(Simulation& sim, Real max_step) = 0;
};

// How the position-based schedules fill an advection step Dt with acoustic steps (dt_ac: the
// acoustic criterion, re-evaluated at every acoustic step; core/step_splitting.hpp).
enum class AcousticSteps {
  EqualSplit,       // ceil(Dt / dt_ac) equal steps that end on Dt
  FullSteps,        // the paper's Algorithm 1: full steps, the last passing Dt by less than one
  FullStepsInside   // full steps while the next one fits: the advection step ends at or before Dt
};

// Throws std::invalid_argument.
std::unique_ptr<Schedule> make_schedule(const std::string& name, AcousticSteps acoustic_steps = AcousticSteps::EqualSplit);
const std::vector<std::string>& schedule_names();

}  // namespace mrsph
