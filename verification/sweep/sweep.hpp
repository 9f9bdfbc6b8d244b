// Sweeps: many independent runs of scenes with overrides, as the convergence, speed-accuracy and
// stability suites need.
//   run_sweep     runs them here, several at a time (each single-threaded), up to `jobs`
//   emit          writes the equivalent `mrsph run` commands for GNU parallel or a Slurm array
//   load          reads the outputs those commands (or an earlier run_sweep) wrote
// Every run writes what `mrsph run` writes (summary.json, observers/*.csv) into
// CACHE/<key>, key = a hash of the scene file's content, the overrides and the end time; a run whose
// complete outputs are already there is not run again, so suites share runs and a sweep can be
// resumed. A run that diverges is an outcome like any other (with time, body and reason).
#pragma once

#include "report/suite_summary.hpp"
#include "scene/scene_loader.hpp"
#include "run/runner.hpp"
#include "suites/suite.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mrsph::verification {

struct SweepRun {
  std::string label;  // for people: "gate b/8 ratio 2 single"
  std::string scene;  // file name in verification/scenes/
  std::vector<std::string> overrides;
  double end_time = 0.0;  // 0: the scene's
  Json config = Json::object();  // what the analysis needs to know about the run
  double wall_limit_s = 0.0;     // stop a run that takes longer (0: no limit); recorded as timed out
};

struct SweepOutcome {
  SweepRun run;
  std::string key;
  bool completed = false;
  bool diverged = false;
  bool timed_out = false;
  Json divergence;       // null unless diverged
  std::string failure;   // an error other than divergence (bad overrides, ...)
  Json cost = Json::object();
  Json compressibility;  // the run summary's (null: no fluid, or a cache written before it existed)
  Json parameters = Json::object();  // the scene's evaluated parameters
  std::vector<ObserverSeries> series;
  bool reused = false;   // loaded from the cache, not run now
};

std::string sweep_key(const SuiteContext& ctx, const SweepRun& run);
std::filesystem::path sweep_cache(const SuiteContext& ctx);  // out_dir/../cache (shared by the suites of a run)

std::vector<SweepOutcome> run_sweep(const SuiteContext& ctx, const std::vector<SweepRun>& runs, int jobs);
// Calls task(0) ... task(count - 1), up to `jobs` at a time, each on one thread of its own (a task
// arena of one), and returns when all are done; the first exception a task threw is rethrown then.
void run_concurrently(std::size_t count, int jobs, const std::function<void(std::size_t)>& task);
// Reads the outcomes from the cache; a run with no outputs there is an outcome with `failure` set.
std::vector<SweepOutcome> load_sweep(const SuiteContext& ctx, const std::vector<SweepRun>& runs);
// Writes commands.txt (one `mrsph run` per line: `parallel < commands.txt`) and slurm_array.sh.
void emit_sweep(const SuiteContext& ctx, const std::vector<SweepRun>& runs, const std::filesystem::path& dir);

// Runs, emits or loads a sweep according to ctx.sweep_mode; when emitting, notes it in the summary
// and returns nothing.
std::vector<SweepOutcome> sweep(const SuiteContext& ctx, const std::vector<SweepRun>& runs, SuiteSummary& summary);
// {"status": completed | diverged | timed out | error, ...} for a summary.
Json outcome_record(const SweepOutcome& outcome);

// Stores a run made elsewhere in a suite (in-process, with its own options) in the cache under the key
// a sweep would use for `run`, so later sweeps reuse it.
void persist_in_cache(const SuiteContext& ctx, const SweepRun& run, const LoadedScene& scene, const RunResult& result);

// The series of an outcome by observer name (throws if absent).
const ObserverSeries& outcome_series(const SweepOutcome& outcome, const std::string& name);

}  // namespace mrsph::verification
