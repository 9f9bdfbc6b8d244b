// Initial velocity fields in scene files (boundary/initial_velocity.hpp):
//   {"type": "uniform", "value": [u, v]}
//   {"type": "womersley", "bottom", "height", "pressure_gradient_amplitude", "angular_frequency",
//    "density", "kinematic_viscosity", "time"}
//   {"type": "cantilever_mode", "clamp_x", "length", "amplitude", "kL"}
//   {"type": "expression", "u": EXPR, "v": EXPR}  (expressions of x, y and the scene's parameters)
#pragma once

#include "boundary/initial_velocity.hpp"
#include "scene/scene_node.hpp"

#include <functional>

namespace mrsph {

// The parent's "initial_velocity" (zero if absent).
InitialVelocity read_initial_velocity(const SceneNode& parent);

// The node's "u" and "v": expressions of x, y (and t if of_time) and the scene's parameters, as a
// velocity of (position, time). Both are evaluated at the origin (and t = 0) here, so a bad
// expression is reported with its key before any particle is made; a parameter named like a
// variable is refused.
std::function<Vec2(const Vec2&, Real)> read_velocity_expressions(const SceneNode& node, bool of_time);

}  // namespace mrsph
