// Builds scenes from JSON text for tests.
#pragma once

#include "scene/scene_loader.hpp"

#include <string>

inline mrsph::LoadedScene scene_from(const std::string& text, const mrsph::SceneLimits& limits = {}) {
  return mrsph::build_scene(mrsph::Json::parse(text), "test-scene.json", limits);
}
