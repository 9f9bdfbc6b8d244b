// A verification suite: runs scenes, measures, checks, and writes its summary, CSVs and figures
// into its own directory. Suites are registered by name (suite_registry.cpp).
#pragma once

#include "report/suite_summary.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mrsph::verification {

// How suites built on sweeps get their runs: run here, emit commands, or merge existing outputs.
enum class SweepMode { Run, Emit, Merge };

struct SuiteContext {
  bool quick = false;
  std::filesystem::path out_dir;                       // this suite's directory
  std::optional<std::filesystem::path> reference_dir;  // ../shared/reference-data, if given
  std::filesystem::path project_dir;                   // for scenes/, scripts/, reference-data/
  int threads = 1;
  int jobs = 1;                        // concurrent single-threaded runs in sweeps
  SweepMode sweep_mode = SweepMode::Run;
  std::function<void(const std::string&)> log;         // progress lines for the terminal

  std::filesystem::path scene(const std::string& name) const { return project_dir / "verification" / "scenes" / name; }
};

using SuiteFunction = std::function<SuiteSummary(const SuiteContext&)>;

struct SuiteEntry {
  std::string name;
  std::string description;
  SuiteFunction run;
};

const std::vector<SuiteEntry>& registered_suites();

}  // namespace mrsph::verification
