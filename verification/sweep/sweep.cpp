#include "sweep/sweep.hpp"

#include "io/atomic_file.hpp"
#include "report/reference_table.hpp"
#include "scene/scene_loader.hpp"
#include "run/run_summary.hpp"

#include <fmt/format.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

namespace mrsph::verification {

namespace {

std::string file_content(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::uint64_t fnv1a(const std::string& text, std::uint64_t hash = 1469598103934665603ull) {
  for (const unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
  return hash;
}

bool complete_outputs(const std::filesystem::path& dir) { return std::filesystem::exists(dir / "summary.json"); }

SweepOutcome read_outcome(const SweepRun& run, const std::string& key, const std::filesystem::path& dir) {
  SweepOutcome out;
  out.run = run;
  out.key = key;
  std::ifstream in(dir / "summary.json");
  if (!in) {
    out.failure = "no outputs in " + dir.string();
    return out;
  }
  const Json summary = Json::parse(in);
  if (summary.contains("failure")) {
    out.failure = summary["failure"].get<std::string>();
    return out;
  }
  out.completed = summary.value("completed", false);
  out.timed_out = summary.value("interrupted", false);
  out.diverged = summary.value("diverged", false);
  out.divergence = summary.value("divergence", Json());
  out.cost = summary.value("cost", Json::object());
  out.compressibility = summary.value("compressibility", Json());
  out.parameters = summary.value("parameters", Json::object());
  for (const Json& file : summary.value("observers", Json::array())) {
    const auto table = read_numeric_table(dir / file.get<std::string>());
    if (!table) continue;
    ObserverSeries s;
    s.name = std::filesystem::path(file.get<std::string>()).stem().string();
    s.columns.assign(table->header.begin() + 1, table->header.end());
    s.time = table->columns[0];
    for (std::size_t k = 0; k < s.time.size(); ++k) {
      std::vector<double> row;
      for (std::size_t c = 1; c < table->columns.size(); ++c) row.push_back(table->columns[c][k]);
      s.values.push_back(std::move(row));
    }
    out.series.push_back(std::move(s));
  }
  return out;
}

// Runs one sweep entry here, single-threaded, and writes mrsph run's outputs into `dir`.
void execute(const SuiteContext& ctx, const SweepRun& run, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  try {
    LoadedScene scene = load_scene(ctx.scene(run.scene), run.overrides);
    if (run.end_time > 0.0) scene.run.end_time = run.end_time;
    RunOptions options;
    options.end_time = scene.run.end_time;
    options.observer_interval = scene.run.observer_interval;
    // A wall-clock budget per run: a run that is too slow ends as interrupted (a data point of its own).
    std::atomic<bool> out_of_time{false};
    const auto start = std::chrono::steady_clock::now();
    if (run.wall_limit_s > 0.0) {
      options.stop_requested = &out_of_time;
      options.progress_interval_s = 0.0;
      options.on_progress = [&](const RunProgress&) {
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > run.wall_limit_s) out_of_time = true;
      };
    }
    const RunResult result = run_simulation(*scene.simulation, *scene.schedule, scene.observers, options);
    write_observer_series(result.series, dir / "observers");
    Json summary = run_summary_json(scene, result, 1);
    summary["label"] = run.label;
    write_file_atomically(dir / "summary.json", summary.dump(2) + "\n");
  } catch (const std::exception& e) {
    write_file_atomically(dir / "summary.json", Json{{"label", run.label}, {"failure", e.what()}}.dump(2) + "\n");
  }
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::filesystem::path sweep_cache(const SuiteContext& ctx) { return ctx.out_dir.parent_path() / "cache"; }

std::string sweep_key(const SuiteContext& ctx, const SweepRun& run) {
  std::uint64_t hash = fnv1a(file_content(ctx.scene(run.scene)));
  for (const std::string& o : run.overrides) hash = fnv1a(o + "\n", hash);
  hash = fnv1a(fmt::format("end={:.17g}", run.end_time), hash);
  return fmt::format("{}-{:016x}", std::filesystem::path(run.scene).stem().string(), hash);
}

void run_concurrently(std::size_t count, int jobs, const std::function<void(std::size_t)>& task) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr first_error;  // an exception may not leave a thread: kept, rethrown after the join
  std::mutex error_mutex;
  auto worker = [&] {
    tbb::task_arena single(1);  // each task single-threaded; concurrency comes from running several
    for (std::size_t k; (k = next++) < count;) {
      try {
        single.execute([&] { task(k); });
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
      }
    }
  };
  const int workers = std::max(1, std::min<int>(jobs, static_cast<int>(count)));
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
}

std::vector<SweepOutcome> run_sweep(const SuiteContext& ctx, const std::vector<SweepRun>& runs, int jobs) {
  const std::filesystem::path cache = sweep_cache(ctx);
  std::vector<SweepOutcome> outcomes(runs.size());
  std::mutex log_mutex;
  run_concurrently(runs.size(), jobs, [&](std::size_t k) {
    const std::string key = sweep_key(ctx, runs[k]);
    const std::filesystem::path dir = cache / key;
    const bool reused = complete_outputs(dir);
    if (!reused) {
      if (ctx.log) {
        std::lock_guard lock(log_mutex);
        ctx.log("sweep: " + runs[k].label);
      }
      execute(ctx, runs[k], dir);
    }
    outcomes[k] = read_outcome(runs[k], key, dir);
    outcomes[k].reused = reused;
  });
  return outcomes;
}

void persist_in_cache(const SuiteContext& ctx, const SweepRun& run, const LoadedScene& scene, const RunResult& result) {
  const std::filesystem::path dir = sweep_cache(ctx) / sweep_key(ctx, run);
  write_observer_series(result.series, dir / "observers");
  Json summary = run_summary_json(scene, result, ctx.threads);
  summary["label"] = run.label;
  write_file_atomically(dir / "summary.json", summary.dump(2) + "\n");
}

std::vector<SweepOutcome> load_sweep(const SuiteContext& ctx, const std::vector<SweepRun>& runs) {
  std::vector<SweepOutcome> outcomes;
  for (const SweepRun& run : runs) {
    const std::string key = sweep_key(ctx, run);
    outcomes.push_back(read_outcome(run, key, sweep_cache(ctx) / key));
    outcomes.back().reused = true;
  }
  return outcomes;
}

void emit_sweep(const SuiteContext& ctx, const std::vector<SweepRun>& runs, const std::filesystem::path& dir) {
  const std::filesystem::path mrsph = ctx.project_dir / "build" / "release" / "solver" / "mrsph";
  std::string commands;
  for (const SweepRun& run : runs) {
    std::string line = shell_quote(mrsph.string()) + " run " + shell_quote(ctx.scene(run.scene).string());
    for (const std::string& o : run.overrides) line += " --set " + shell_quote(o);
    if (run.end_time > 0.0) line += fmt::format(" --end-time {:.17g}", run.end_time);
    line += " --threads 1 --quiet --out " + shell_quote((sweep_cache(ctx) / sweep_key(ctx, run)).string());
    commands += line + "\n";
  }
  write_file_atomically(dir / "commands.txt", commands);
  std::string slurm = fmt::format(
      "#!/bin/bash\n# One array task per run: sbatch {}\n#SBATCH --array=0-{}\n#SBATCH --cpus-per-task=1\n"
      "command=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" {})\neval \"$command\"\n",
      (dir / "slurm_array.sh").string(), runs.size() - 1, shell_quote((dir / "commands.txt").string()));
  write_file_atomically(dir / "slurm_array.sh", slurm);
  std::filesystem::permissions(dir / "slurm_array.sh", std::filesystem::perms::owner_exec, std::filesystem::perm_options::add);
}

const ObserverSeries& outcome_series(const SweepOutcome& outcome, const std::string& name) {
  try {
    return series_named(outcome.series, name);
  } catch (const std::runtime_error&) {
    throw std::runtime_error("run '" + outcome.run.label + "' has no observer '" + name + "'");
  }
}

std::vector<SweepOutcome> sweep(const SuiteContext& ctx, const std::vector<SweepRun>& runs, SuiteSummary& summary) {
  if (ctx.sweep_mode == SweepMode::Emit) {
    emit_sweep(ctx, runs, ctx.out_dir);
    summary.note_skipped("the runs of this suite", fmt::format("{} commands emitted to {} (run them, then verify ... --merge)",
                                                               runs.size(), (ctx.out_dir / "commands.txt").string()));
    return {};
  }
  return ctx.sweep_mode == SweepMode::Merge ? load_sweep(ctx, runs) : run_sweep(ctx, runs, ctx.jobs);
}

Json outcome_record(const SweepOutcome& o) {
  if (!o.failure.empty()) return {{"status", "error"}, {"error", o.failure}};
  if (o.diverged) return {{"status", "diverged"}, {"divergence", o.divergence}};
  if (o.timed_out) return {{"status", "timed out"}};
  return {{"status", "completed"}};
}

}  // namespace mrsph::verification
