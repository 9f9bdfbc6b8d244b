// The linear flutter theory of the fish in verify --suite fish (theory/plate_flutter.hpp): the
// scene's body in a uniform stream, its modes at the scene's Young's modulus and the modulus below
// which it flutters, tethered (the cable as a lateral spring at the nose) and pinned.
#pragma once

#include "report/suite_summary.hpp"
#include "scene/scene_loader.hpp"

namespace mrsph::verification {

// cable_tension: the run's mean drag (the cable's lateral stiffness is tension / rest length).
// With sweep, also the least-damped mode's growth rate and frequency over E = 2 ... 500.
Json fish_linear_theory(const LoadedScene& scene, double cable_tension, bool sweep);

}  // namespace mrsph::verification
