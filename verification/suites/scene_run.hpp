// Helpers shared by suites: run a scene file with overrides and collect what it produced; render
// figures with the project's matplotlib scripts.
#pragma once

#include "report/suite_summary.hpp"
#include "scene/scene_loader.hpp"
#include "run/runner.hpp"
#include "suites/suite.hpp"

#include <string>
#include <vector>

namespace mrsph::verification {

struct SceneRun {
  LoadedScene scene;
  RunResult result;
};

// Loads the scene (with overrides), asks `configure` for the run options (it may read the loaded
// scene's parameters), and runs it; end time and observer interval come from the scene unless set.
SceneRun run_scene(const SuiteContext& ctx, const std::string& scene_file, const std::vector<std::string>& overrides,
                   const std::function<RunOptions(const LoadedScene&)>& configure = {});

// Runs task(case_ctx, k) for k < count: with --jobs > 1 several at once (each run single-threaded,
// the log lines serialised), else one after another. For suites whose cases are independent runs.
void run_cases(const SuiteContext& ctx, std::size_t count, const std::function<void(const SuiteContext&, std::size_t)>& task);

// The cost block of the summary contract for a finished run.
Json cost_json(const SceneRun& run);
// The fluid's largest density deviation and Mach number over the run (null without a fluid).
Json compressibility_record(const SceneRun& run);
// The divergence record (null if none).
Json divergence_record(const SceneRun& run);

// Runs `/usr/bin/python3 scripts/<script> <dir>`; returns the figure files it reported, or notes
// in the summary why figures were skipped (python or matplotlib missing, script failure).
void render_figures(const SuiteContext& ctx, const std::string& script, SuiteSummary& summary);

}  // namespace mrsph::verification
