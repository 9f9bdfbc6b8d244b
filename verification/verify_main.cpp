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
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#ifndef MRSPH_SOURCE_DIR
#define MRSPH_SOURCE_DIR "."
#endif

namespace fs = std::filesystem;
using mrsph::Json;

int main(int argc, char** argv) {
  std::string suite_list_help;
  for (const auto& s : mrsph::verification::registered_suites())
    suite_list_help += fmt::format("  {:<18} {}\n", s.name, s.description);

  CLI::App app{"verify: runs the verification suites of mrsph and checks the results against analytic solutions,\n"
               "published benchmarks and experiments. Each suite writes summary.json (metrics, checks with\n"
               "value / reference / tolerance / verdict, cost), CSVs and figures into its own directory.\n\n"
               "Suites:\n" + suite_list_help + "  all                every suite\n\n"
               "Exit status: 0 if every check passed; 1 if a check failed; 2 on bad usage or input."};
  std::vector<std::string> suites;
  bool quick = false;
  std::string out_dir, reference_dir, project_dir = MRSPH_SOURCE_DIR, existing_run, baseline_file, write_baseline, rules_file;
  int threads = 0;
  app.add_option("--suite", suites, "suite(s) to run (repeatable, or 'all')");
  app.add_option("--run", existing_run, "an existing run directory to compare with the baseline (instead of running suites)")
      ->check(CLI::ExistingDirectory);
  app.add_option("--compare-baseline", baseline_file,
                 "compare the run's metrics with a baseline (reports/baseline/quick.json); writes regression.md, "
                 "exit status 1 on a regression")->check(CLI::ExistingFile);
  app.add_option("--write-baseline", write_baseline, "write a baseline of the run's metrics to this file (needs --rules)");
  int jobs = 0;
  bool emit = false, merge = false;
  app.add_option("--jobs", jobs, "concurrent single-threaded runs in sweep suites and the full valve suite (default: the hardware threads)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--emit-commands", emit,
               "sweep suites: write their runs as mrsph commands (DIR/<suite>/commands.txt for GNU parallel, "
               "slurm_array.sh for a Slurm array) instead of running them");
  app.add_flag("--merge", merge, "sweep suites: analyse runs already done by the emitted commands (in DIR/cache)");
  bool tables = false;
  app.add_flag("--paper-tables", tables,
               "print the paper's Tables 2, 3 and 5 with this run's numbers (from --run DIR or the suites just run); "
               "also written to DIR/paper_tables.md");
  app.add_option("--rules", rules_file, "which metrics a new baseline watches, with tolerances (reports/baseline/rules.json)")
      ->check(CLI::ExistingFile);
  app.add_flag("--quick", quick, "CI-sized runs (minutes) instead of the full ones");
  app.add_option("--out", out_dir, "run directory (default: reports/runs/<date-time>[-quick])");
  app.add_option("--reference-dir", reference_dir,
                 "reference data (e.g. ../shared/reference-data); comparisons that need it are skipped, and said so, without it");
  app.add_option("--threads", threads, "worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  app.add_option("--project-dir", project_dir, "the project's source tree (scenes, scripts)")->check(CLI::ExistingDirectory);
  CLI11_PARSE(app, argc, argv);

  if (suites.empty() && existing_run.empty()) {
    fmt::print(stderr, "error: give --suite NAME to run suites, or --run DIR to use an existing run\n");
    return 2;
  }
  if (!write_baseline.empty() && rules_file.empty()) {
    fmt::print(stderr, "error: --write-baseline needs --rules (reports/baseline/rules.json)\n");
    return 2;
  }
  const auto& registry = mrsph::verification::registered_suites();
  std::vector<const mrsph::verification::SuiteEntry*> selected;
  for (const std::string& name : suites) {
    if (name == "all") {
      for (const auto& s : registry) selected.push_back(&s);
      continue;
    }
    const auto it = std::find_if(registry.begin(), registry.end(), [&](const auto& s) { return s.name == name; });
    if (it == registry.end()) {
      fmt::print(stderr, "error: --suite: unknown suite '{}'; run verify --help for the list\n", name);
      return 2;
    }
    selected.push_back(&*it);
  }
  if (!reference_dir.empty() && !fs::is_directory(reference_dir)) {
    fmt::print(stderr, "error: --reference-dir: '{}' is not a directory\n", reference_dir);
    return 2;
  }

  const int used_threads = threads > 0 ? threads : tbb::info::default_concurrency();
  return mrsph::run_with_threads(used_threads, [&]() -> int {

  fs::path run_dir = existing_run.empty() ? fs::path(out_dir) : fs::path(existing_run);
  if (run_dir.empty()) {
    const std::time_t now = std::time(nullptr);
    run_dir = fs::path(project_dir) / "reports" / "runs" / fmt::format("{:%Y%m%d-%H%M%S}{}", fmt::localtime(now), quick ? "-quick" : "");
  }

  bool all_passed = true;
  Json index = Json::array();
  for (const auto* entry : selected) {
    mrsph::verification::SuiteContext ctx;
    ctx.quick = quick;
    ctx.out_dir = run_dir / entry->name;
    if (!reference_dir.empty()) ctx.reference_dir = fs::path(reference_dir);
    ctx.project_dir = project_dir;
    ctx.threads = used_threads;
    ctx.jobs = jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    ctx.sweep_mode = emit ? mrsph::verification::SweepMode::Emit
                          : merge ? mrsph::verification::SweepMode::Merge : mrsph::verification::SweepMode::Run;
    ctx.log = [](const std::string& line) { fmt::print(stderr, "  {}\n", line); };
    fs::create_directories(ctx.out_dir);
    fmt::print("== suite {} ({}) -> {}\n", entry->name, quick ? "quick" : "full", ctx.out_dir.string());
    const auto start = std::chrono::steady_clock::now();
    try {
      const auto summary = entry->run(ctx);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      fmt::print("{}", summary.checks_table());
      fmt::print("== suite {}: {} in {:.1f} s\n\n", entry->name, summary.passed() ? "PASSED" : "FAILED", seconds);
      all_passed = all_passed && summary.passed();
      index.push_back({{"suite", entry->name}, {"passed", summary.passed()}, {"summary", entry->name + "/summary.json"},
                       {"wall_s", seconds}});
    } catch (const std::exception& e) {
      fmt::print(stderr, "error: suite {}: {}\n", entry->name, e.what());
      all_passed = false;
      index.push_back({{"suite", entry->name}, {"passed", false}, {"error", e.what()}});
    }
  }
  if (!selected.empty()) {
    std::vector<std::string> names;
    for (const auto* entry : selected) names.push_back(entry->name);
    mrsph::verification::ReportContext report_context;
    report_context.mode = quick ? "quick" : "full";
    report_context.threads = used_threads;
    report_context.commit = mrsph::verification::git_commit(project_dir);
    for (int k = 0; k < argc; ++k) report_context.command_line += (k ? " " : "") + std::string(argv[k]);
    mrsph::write_file_atomically(run_dir / "report.md", mrsph::verification::markdown_report(run_dir, names, report_context));
    const Json run_index = {{"mode", quick ? "quick" : "full"}, {"passed", all_passed}, {"threads", used_threads}, {"suites", index}};
    mrsph::write_file_atomically(run_dir / "index.json", run_index.dump(2) + "\n");
    fmt::print("verify: {} ({})\n", all_passed ? "all checks passed" : "some checks FAILED", (run_dir / "index.json").string());
  }
  try {
    if (tables) {
      const std::string md = mrsph::verification::paper_tables(run_dir, project_dir);
      mrsph::write_file_atomically(run_dir / "paper_tables.md", md);
      fmt::print("{}", md);
    }
    if (!write_baseline.empty()) {
      std::ifstream rules_in(rules_file);
      const Json baseline = mrsph::verification::make_baseline(run_dir, Json::parse(rules_in));
      mrsph::write_file_atomically(write_baseline, baseline.dump(2) + "\n");
      fmt::print("verify: baseline of {} written to {}\n", run_dir.string(), write_baseline);
    }
    if (!baseline_file.empty()) {
      std::ifstream in(baseline_file);
      const auto results = mrsph::verification::compare_to_baseline(Json::parse(in), run_dir);
      const std::string report = mrsph::verification::regression_report(results);
      mrsph::write_file_atomically(run_dir / "regression.md", "# Regression against " + baseline_file + "\n\n" + report);
      bool regressed = false;
      for (const auto& c : results) regressed = regressed || !c.passed;
      fmt::print("{}", report);
      fmt::print("verify: {} ({})\n", regressed ? "REGRESSION against the baseline" : "no regression against the baseline",
                 (run_dir / "regression.md").string());
      all_passed = all_passed && !regressed;
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: baseline: {}\n", e.what());
    return 2;
  }
  return all_passed ? 0 : 1;
  });
}
