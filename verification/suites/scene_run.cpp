#include "suites/scene_run.hpp"

#include "run/run_summary.hpp"
#include "sweep/sweep.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>

namespace mrsph::verification {

SceneRun run_scene(const SuiteContext& ctx, const std::string& scene_file, const std::vector<std::string>& overrides,
                   const std::function<RunOptions(const LoadedScene&)>& configure) {
  SceneRun run{load_scene(ctx.scene(scene_file), overrides), {}};
  RunOptions options = configure ? configure(run.scene) : RunOptions{};
  if (options.end_time <= 0.0) options.end_time = run.scene.run.end_time;
  // Long runs report each tenth of their simulated time once they have taken half a minute (cases
  // that run concurrently would otherwise stay silent for the whole suite).
  double next_tenth = 0.1;
  std::string label = run.scene.name;
  for (const std::string& o : overrides) label += " " + o;
  if (ctx.log && !options.on_progress) options.on_progress = [&](const RunProgress& p) {
    const double fraction = p.end_time > 0.0 ? p.time / p.end_time : 0.0;
    if (p.wall_s < 30.0 || fraction < next_tenth) return;
    ctx.log(fmt::format("    {}: t = {:.4g} of {:g} ({:.0f} %), {:.0f} s", label, p.time, p.end_time, 100.0 * fraction, p.wall_s));
    next_tenth = std::floor(fraction * 10.0 + 1.0) / 10.0;
  };
  if (options.observer_interval <= 0.0) options.observer_interval = run.scene.run.observer_interval;
  run.result = run_simulation(*run.scene.simulation, *run.scene.schedule, run.scene.observers, options);
  return run;
}

void run_cases(const SuiteContext& ctx, std::size_t count, const std::function<void(const SuiteContext&, std::size_t)>& task) {
  std::mutex log_mutex;
  SuiteContext case_ctx = ctx;
  if (ctx.log) case_ctx.log = [&](const std::string& line) {
    std::lock_guard lock(log_mutex);
    ctx.log(line);
  };
  if (ctx.jobs > 1 && count > 1) {
    run_concurrently(count, ctx.jobs, [&](std::size_t k) { task(case_ctx, k); });
  } else {
    for (std::size_t k = 0; k < count; ++k) task(case_ctx, k);
  }
}

Json cost_json(const SceneRun& run) {
  const RunResult& r = run.result;
  const double particles = static_cast<double>(run.scene.simulation->particle_count());
  Json cost;
  cost["wall_s"] = r.wall_s;
  cost["cpu_s"] = r.cpu_s;
  cost["particles"] = particle_counts(*run.scene.simulation);
  cost["steps"] = step_counts(r.steps);
  // Particle updates per second: particles (all bodies) times acoustic steps, per wall second.
  cost["particle_updates_per_s"] = r.wall_s > 0.0 ? particles * static_cast<double>(r.steps.acoustic) / r.wall_s : 0.0;
  return cost;
}

Json compressibility_record(const SceneRun& run) {
  if (!run.scene.simulation->has_fluid()) return nullptr;
  return compressibility_json(run.result.compressibility);
}

Json divergence_record(const SceneRun& run) {
  if (!run.result.divergence) return nullptr;
  return divergence_json(*run.result.divergence);
}

void render_figures(const SuiteContext& ctx, const std::string& script, SuiteSummary& summary) {
  const std::filesystem::path python = "/usr/bin/python3";
  const std::filesystem::path path = ctx.project_dir / "scripts" / script;
  if (!std::filesystem::exists(python)) {
    summary.note_skipped("figures", "/usr/bin/python3 not found (install python3-matplotlib: scripts/install-deps.sh)");
    return;
  }
  const std::string command = fmt::format("'{}' '{}' '{}' 2>&1", python.string(), path.string(), ctx.out_dir.string());
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) {
    summary.note_skipped("figures", "could not start " + script);
    return;
  }
  std::string output;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = ::pclose(pipe);
  Json figures = Json::array();
  std::size_t start = 0;
  while (start < output.size()) {
    const std::size_t end = output.find('\n', start);
    const std::string line = output.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (line.rfind("figure: ", 0) == 0) figures.push_back(line.substr(8));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  summary.extra()["figures"] = figures;
  if (status != 0) summary.note_skipped("figures", script + " failed: " + output.substr(0, 400));
}

}  // namespace mrsph::verification
