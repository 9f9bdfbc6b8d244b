// Initial velocity fields in scene files (boundary/initial_velocity.hpp):
//   {"type": "uniform", "value": [u, v]}
//   {"type": "womersley", "bottom", "height", "pressure_gradient_amplitude", "angular_frequency",
//    "density", "kinematic_viscosity", "time"}
//   {"type": "cantilever_mode", "clamp_x", "length", "amplitude", "kL"}
//   {"type": "expression", "u": EXPR, "v": EXPR}  (expressions of x, y and the scene's parameters)
#pragma once

#include "boundary/initial_velocity.hpp"
#include "scene/scene_node.hpp"

namespace mrsph {

// The parent's "initial_velocity" (zero if absent).
InitialVelocity read_initial_velocity(const SceneNode& parent);

}  // namespace mrsph
