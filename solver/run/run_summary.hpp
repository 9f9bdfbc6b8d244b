// The JSON summary of one `mrsph run`: what ran (the scene after overrides), on what, how far it
// got, what it cost, how compressible its fluid became, and where its outputs are.
#pragma once

#include "scene/scene_loader.hpp"
#include "run/runner.hpp"

#include <nlohmann/json.hpp>

namespace mrsph {

nlohmann::ordered_json particle_counts(const Simulation& sim);
nlohmann::ordered_json step_counts(const StepCounters& steps);
nlohmann::ordered_json divergence_json(const DivergenceInfo& info);
// The largest density deviation and Mach number of the fluid, with when and where.
nlohmann::ordered_json compressibility_json(const CompressibilityRecord& record);
nlohmann::ordered_json run_summary_json(const LoadedScene& scene, const RunResult& result, int threads);

}  // namespace mrsph
