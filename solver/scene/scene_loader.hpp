// Scene files: a JSON description of one case (bodies with shapes, resolution and materials,
// boundaries, observers, schedule, end time), turned into a ready-to-run Simulation. The format
// is documented in verification/scenes/README.md. Any value can be overridden before the scene
// is built ("fluid.dp=0.05", "parameters.resolution=80"); numbers may be expressions over the
// scene's "parameters".
#pragma once

#include "observers/point_observer.hpp"
#include "scene/scene_node.hpp"
#include "simulation/simulation.hpp"
#include "time/schedule.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace mrsph {

struct SceneLimits {
  double max_particles = 2.0e7;  // refused before allocation: about 4 GB of state
};

struct SceneRunSettings {
  Real end_time = 0.0;
  Real observer_interval = 0.0;  // 0: every advection step
  Real snapshot_interval = 0.0;  // 0: none
};

struct LoadedScene {
  std::string file;
  std::string name;
  std::string description;
  std::string units;
  Json document;  // after overrides
  ParameterTable parameters;
  std::unique_ptr<Simulation> simulation;
  std::unique_ptr<Schedule> schedule;
  std::vector<ObserverSpec> observers;
  SceneRunSettings run;
};

// Reads and parses a scene file; InputError on a missing file or invalid JSON (with line/column).
Json read_scene_document(const std::filesystem::path& path);
// Applies "path=value" (path with '.' and [index]; value parsed as JSON, else taken as a string);
// "path=null" removes an optional key (an inflow, say).
void apply_override(Json& document, const std::string& assignment, const std::string& file);
// Builds the simulation (particles generated, relations built, initialised).
LoadedScene build_scene(const Json& document, const std::string& file, const SceneLimits& limits = {});
LoadedScene load_scene(const std::filesystem::path& path, const std::vector<std::string>& overrides,
                       const SceneLimits& limits = {});

}  // namespace mrsph
