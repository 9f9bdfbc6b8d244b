// Inflow profiles and open boundaries in scene files (boundary/inflow.hpp, boundary/open_boundary.hpp).
//   profile: {"type": "parabolic_channel", "bottom", "height", "mean_velocity", "ramp_time"}
//            {"type": "womersley", "bottom", "height", "pressure_gradient_amplitude",
//             "angular_frequency", "density", "kinematic_viscosity"}
//            {"type": "expression", "u": EXPR, "v": EXPR}  (of x, y, t and the scene's parameters)
//   "inflow":          {"buffer": REGION, "profile": PROFILE}  (a periodic channel's velocity reset)
//   "open_boundaries": [{"name", "axis": "x"|"y", "side": "lower"|"upper" (the end of the domain it
//                        is on), "plane", "width", "span": [lo, hi] (the buffer's extent along the
//                        plane), "condition": "velocity"|"pressure", "profile": PROFILE (velocity),
//                        "pressure": EXPR of t (pressure), "reflection_time" (pressure; 0: reflecting),
//                        "entering_pressure": "static"|"total" (pressure: what p_b is where fluid enters),
//                        "normal_velocity": "bins"|"smooth" (pressure: the buffer's u_n per bin or fitted)}]
#pragma once

#include "boundary/inflow.hpp"
#include "boundary/open_boundary.hpp"
#include "scene/scene_node.hpp"
#include "simulation/simulation.hpp"

#include <vector>

namespace mrsph {

InflowProfile read_inflow_profile(const SceneNode& node);
InflowBuffer read_inflow(const SceneNode& node);

// Reads "open_boundaries" and checks them against the simulation's box and bodies (a buffer on a
// periodic axis, outside the box, crossing a wall or solid, or with no fluid in it is refused).
std::vector<OpenBoundary> read_open_boundaries(const SceneNode& root, const Simulation& sim);

}  // namespace mrsph
