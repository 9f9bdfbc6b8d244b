// verify: the verification and benchmark harness. See `verify --help`.
#include "core/thread_limit.hpp"
#include "io/atomic_file.hpp"
#include "report/markdown_report.hpp"
#include "report/paper_tables.hpp"
#include "report/regression.hpp"
#include "suites/suite.hpp"

#include <CLI/CLI.hpp>
#include <fmt/chrono.h>
#include <fmt/format.h>
#include <tbb/info.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#ifndef MRSPH_SOURCE_DIR
#define MRSPH_SOURCE_DIR "."
#endif

namespace fs = std::filesystem;
namespace verification = mrsph::verification;
using mrsph::Json;

namespace {

// What the command line asked for.
struct Options {
  std::vector<std::string> suites;
  bool quick = false, emit = false, merge = false, tables = false;
  std::string out_dir, reference_dir, project_dir = MRSPH_SOURCE_DIR, existing_run, baseline_file, write_baseline,
      rules_file;
  int threads = 0, jobs = 0;
};

std::string usage_text() {
  std::string suite_list;
  for (const auto& s : verification::registered_suites()) suite_list += fmt::format("  {:<18} {}\n", s.name, s.description);
  return "verify: runs the verification suites of mrsph and checks the results against analytic solutions,\n"
         "published benchmarks and experiments. Each suite writes summary.json (metrics, checks with\n"
         "value / reference / tolerance / verdict, cost), CSVs and figures into its own directory.\n\n"
         "Suites:\n" + suite_list + "  all                every suite\n\n"
         "Exit status: 0 if every check passed; 1 if a check failed; 2 on bad usage or input.";
}

void add_run_options(CLI::App& app, Options& o) {
  app.add_option("--suite", o.suites, "suite(s) to run (repeatable, or 'all')");
  app.add_flag("--quick", o.quick, "CI-sized runs (minutes) instead of the full ones");
  app.add_option("--out", o.out_dir, "run directory (default: reports/runs/<date-time>[-quick])");
  app.add_option("--reference-dir", o.reference_dir,
                 "reference data (e.g. ../shared/reference-data); comparisons that need it are skipped, and said so, without it");
  app.add_option("--threads", o.threads, "worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  app.add_option("--project-dir", o.project_dir, "the project's source tree (scenes, scripts)")->check(CLI::ExistingDirectory);
  app.add_option("--jobs", o.jobs, "concurrent single-threaded runs in sweep suites and the full valve suite (default: the hardware threads)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--emit-commands", o.emit,
               "sweep suites: write their runs as mrsph commands (DIR/<suite>/commands.txt for GNU parallel, "
               "slurm_array.sh for a Slurm array) instead of running them");
  app.add_flag("--merge", o.merge, "sweep suites: analyse runs already done by the emitted commands (in DIR/cache)");
}

void add_report_options(CLI::App& app, Options& o) {
  app.add_option("--run", o.existing_run, "an existing run directory to compare with the baseline (instead of running suites)")
      ->check(CLI::ExistingDirectory);
  app.add_option("--compare-baseline", o.baseline_file,
                 "compare the run's metrics with a baseline (reports/baseline/quick.json); writes regression.md, "
                 "exit status 1 on a regression")->check(CLI::ExistingFile);
  app.add_option("--write-baseline", o.write_baseline, "write a baseline of the run's metrics to this file (needs --rules)");
  app.add_flag("--paper-tables", o.tables,
               "print the paper's Tables 2, 3 and 5 with this run's numbers (from --run DIR or the suites just run); "
               "also written to DIR/paper_tables.md");
  app.add_option("--rules", o.rules_file, "which metrics a new baseline watches, with tolerances (reports/baseline/rules.json)")
      ->check(CLI::ExistingFile);
}

// The suites named on the command line; throws std::invalid_argument on a bad combination or name.
std::vector<const verification::SuiteEntry*> select_suites(const Options& o) {
  if (o.suites.empty() && o.existing_run.empty())
    throw std::invalid_argument("give --suite NAME to run suites, or --run DIR to use an existing run");
  if (!o.write_baseline.empty() && o.rules_file.empty())
    throw std::invalid_argument("--write-baseline needs --rules (reports/baseline/rules.json)");
  if (!o.reference_dir.empty() && !fs::is_directory(o.reference_dir))
    throw std::invalid_argument(fmt::format("--reference-dir: '{}' is not a directory", o.reference_dir));
  const auto& registry = verification::registered_suites();
  std::vector<const verification::SuiteEntry*> selected;
  for (const std::string& name : o.suites) {
    if (name == "all") {
      for (const auto& s : registry) selected.push_back(&s);
      continue;
    }
    const auto it = std::find_if(registry.begin(), registry.end(), [&](const auto& s) { return s.name == name; });
    if (it == registry.end())
      throw std::invalid_argument(fmt::format("--suite: unknown suite '{}'; run verify --help for the list", name));
    selected.push_back(&*it);
  }
  return selected;
}

fs::path run_directory(const Options& o) {
  if (!o.existing_run.empty()) return o.existing_run;
  if (!o.out_dir.empty()) return o.out_dir;
  const std::time_t now = std::time(nullptr);
  return fs::path(o.project_dir) / "reports" / "runs" / fmt::format("{:%Y%m%d-%H%M%S}{}", fmt::localtime(now), o.quick ? "-quick" : "");
}

verification::SuiteContext suite_context(const Options& o, const fs::path& out_dir, int threads) {
  verification::SuiteContext ctx;
  ctx.quick = o.quick;
  ctx.out_dir = out_dir;
  if (!o.reference_dir.empty()) ctx.reference_dir = fs::path(o.reference_dir);
  ctx.project_dir = o.project_dir;
  ctx.threads = threads;
  ctx.jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  ctx.sweep_mode = o.emit ? verification::SweepMode::Emit : o.merge ? verification::SweepMode::Merge : verification::SweepMode::Run;
  ctx.log = [](const std::string& line) { fmt::print(stderr, "  {}\n", line); };
  return ctx;
}

// Runs one suite, prints its checks, and returns its entry of index.json.
Json run_suite(const verification::SuiteEntry& entry, const verification::SuiteContext& ctx) {
  fs::create_directories(ctx.out_dir);
  fmt::print("== suite {} ({}) -> {}\n", entry.name, ctx.quick ? "quick" : "full", ctx.out_dir.string());
  const auto start = std::chrono::steady_clock::now();
  try {
    const auto summary = entry.run(ctx);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fmt::print("{}", summary.checks_table());
    fmt::print("== suite {}: {} in {:.1f} s\n\n", entry.name, summary.passed() ? "PASSED" : "FAILED", seconds);
    return {{"suite", entry.name}, {"passed", summary.passed()}, {"summary", entry.name + "/summary.json"}, {"wall_s", seconds}};
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: suite {}: {}\n", entry.name, e.what());
    return {{"suite", entry.name}, {"passed", false}, {"error", e.what()}};
  }
}

// report.md and index.json of the suites just run.
void write_run_index(const Options& o, const fs::path& run_dir, const Json& index, bool all_passed, int threads,
                     const std::string& command_line) {
  std::vector<std::string> names;
  for (const Json& entry : index) names.push_back(entry["suite"].get<std::string>());
  verification::ReportContext report_context;
  report_context.mode = o.quick ? "quick" : "full";
  report_context.threads = threads;
  report_context.commit = verification::git_commit(o.project_dir);
  report_context.command_line = command_line;
  mrsph::write_file_atomically(run_dir / "report.md", verification::markdown_report(run_dir, names, report_context));
  const Json run_index = {{"mode", o.quick ? "quick" : "full"}, {"passed", all_passed}, {"threads", threads}, {"suites", index}};
  mrsph::write_file_atomically(run_dir / "index.json", run_index.dump(2) + "\n");
  fmt::print("verify: {} ({})\n", all_passed ? "all checks passed" : "some checks FAILED", (run_dir / "index.json").string());
}

// Compares the run with the baseline and writes regression.md; true if nothing regressed.
bool compare_with_baseline(const Options& o, const fs::path& run_dir) {
  std::ifstream in(o.baseline_file);
  const auto results = verification::compare_to_baseline(Json::parse(in), run_dir);
  const std::string report = verification::regression_report(results);
  mrsph::write_file_atomically(run_dir / "regression.md", "# Regression against " + o.baseline_file + "\n\n" + report);
  bool regressed = false;
  for (const auto& c : results) regressed = regressed || !c.passed;
  fmt::print("{}", report);
  fmt::print("verify: {} ({})\n", regressed ? "REGRESSION against the baseline" : "no regression against the baseline",
             (run_dir / "regression.md").string());
  return !regressed;
}

// The paper's tables, a new baseline and the comparison with the old one, as asked; false on a regression.
bool report_on_run(const Options& o, const fs::path& run_dir) {
  if (o.tables) {
    const std::string md = verification::paper_tables(run_dir, o.project_dir);
    mrsph::write_file_atomically(run_dir / "paper_tables.md", md);
    fmt::print("{}", md);
  }
  if (!o.write_baseline.empty()) {
    std::ifstream rules_in(o.rules_file);
    const Json baseline = verification::make_baseline(run_dir, Json::parse(rules_in));
    mrsph::write_file_atomically(o.write_baseline, baseline.dump(2) + "\n");
    fmt::print("verify: baseline of {} written to {}\n", run_dir.string(), o.write_baseline);
  }
  return o.baseline_file.empty() || compare_with_baseline(o, run_dir);
}

int execute(const Options& o, const std::vector<const verification::SuiteEntry*>& selected, int threads,
            const std::string& command_line) {
  const fs::path run_dir = run_directory(o);
  bool all_passed = true;
  Json index = Json::array();
  for (const auto* entry : selected) {
    index.push_back(run_suite(*entry, suite_context(o, run_dir / entry->name, threads)));
    all_passed = all_passed && index.back()["passed"].get<bool>();
  }
  if (!selected.empty()) write_run_index(o, run_dir, index, all_passed, threads, command_line);
  try {
    all_passed = report_on_run(o, run_dir) && all_passed;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: baseline: {}\n", e.what());
    return 2;
  }
  return all_passed ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  // Line-buffered even into a pipe (CI's log): a suite's checks are otherwise flushed in 4 KB pieces
  // and the next suite's progress lines (stderr) land in the middle of a check's line.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  Options options;
  CLI::App app{usage_text()};
  add_run_options(app, options);
  add_report_options(app, options);
  CLI11_PARSE(app, argc, argv);

  std::vector<const verification::SuiteEntry*> selected;
  try {
    selected = select_suites(options);
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  }
  std::string command_line;
  for (int k = 0; k < argc; ++k) command_line += (k ? " " : "") + std::string(argv[k]);
  const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  return mrsph::run_with_threads(threads, [&]() -> int { return execute(options, selected, threads, command_line); });
}
