#include "time/schedule.hpp"

#include "time/position_verlet_schedule.hpp"
#include "time/velocity_verlet_schedule.hpp"

#include <stdexcept>

namespace mrsph {

const std::vector<std::string>& schedule_names() {
  static const std::vector<std::string> names{"multi_step_position_verlet", "single_step_position_verlet",
                                              "multi_step_velocity_verlet"};
  return names;
}

std::unique_ptr<Schedule> make_schedule(const std::string& name, AcousticSteps acoustic_steps) {
  if (name == "multi_step_position_verlet") return std::make_unique<PositionVerletSchedule>(false, acoustic_steps);
  if (name == "single_step_position_verlet") return std::make_unique<PositionVerletSchedule>(true, acoustic_steps);
  if (name == "multi_step_velocity_verlet") return std::make_unique<VelocityVerletSchedule>();
  std::string known;
  for (const auto& n : schedule_names()) known += (known.empty() ? "\"" : ", \"") + n + "\"";
  throw std::invalid_argument("unknown schedule \"" + name + "\", expected one of " + known);
}

}  // namespace mrsph
