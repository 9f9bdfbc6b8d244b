// The bodies of a scene file (verification/scenes/README.md): the fluid, walls and solids with their
// particles generated (each checked against the particle budget and the domain), and the contacts
// between solids or a solid and a wall. Each reader consumes its node and reports bad values by
// file, key and value (InputError).
#pragma once

#include "boundary/initial_velocity.hpp"
#include "boundary/wall_body.hpp"
#include "fluid/fluid_body.hpp"
#include "geometry/shapes.hpp"
#include "neighbor/domain_box.hpp"
#include "scene/scene_node.hpp"
#include "simulation/simulation.hpp"
#include "solid/solid_body.hpp"
#include "solid/solid_contact.hpp"

namespace mrsph {

// Each reader returns the body and its region (for the overlap checks) and takes its particles from
// `budget`. The fluid's initial velocity is returned apart: it is evaluated again after a relaxation.
FluidBody read_fluid(const SceneNode& node, const DomainBox& box, double& budget, ShapePtr& region,
                     InitialVelocity& velocity);
WallBody read_wall(const SceneNode& node, const DomainBox& box, double& budget, ShapePtr& region);
SolidBody read_solid(const SceneNode& node, const DomainBox& box, double& budget, ShapePtr& region);

// A contact of two solids, or of a solid and a wall (the wall becomes the second body), by name.
SolidContact read_solid_contact(const SceneNode& node, const Simulation& sim);

}  // namespace mrsph
