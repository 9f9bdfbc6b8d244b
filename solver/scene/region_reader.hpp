// Regions and fill patterns in scene files.
//   {"rectangle": {"lower": [x, y], "upper": [x, y]}}
//   {"circle": {"center": [x, y], "radius": r}}
//   {"polygon": {"vertices": [[x, y], ...]}}
//   {"union": [REGION, ...]}   {"intersection": [REGION, ...]}
//   {"difference": {"base": REGION, "subtract": [REGION, ...]}}
// Fill: {"pattern": "lattice" | "rings", "origin": [x, y], "center": [x, y], "radius": r,
//        "clearance": 0.5}  (rings need center and radius; clearance in units of dp)
#pragma once

#include "geometry/particle_generator.hpp"
#include "geometry/shapes.hpp"
#include "scene/scene_node.hpp"

namespace mrsph {

ShapePtr read_region(const SceneNode& parent, const std::string& key);
FillSpec read_fill(const SceneNode& parent, const std::string& key);

}  // namespace mrsph
