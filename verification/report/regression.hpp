// Regression against a committed baseline of metrics (reports/baseline/*.json). A baseline lists,
// per suite and run, the metrics to watch, each with its value and a tolerance with its reason:
//   { "suites": { "womersley": { "Wo=5 H/dp=20": { "l2_error": { "value": 0.0149,
//       "tolerance": 0.0, "relative": 0.1, "reason": "..." } } } } }
// compare_to_baseline reads DIR/<suite>/summary.json for every suite of the baseline and reports
// every metric: regressed if |new - baseline| > max(tolerance, relative |baseline|), or if a run
// or metric is missing or the run diverged.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace mrsph::verification {

struct MetricComparison {
  std::string suite, run, metric;
  double baseline = 0.0, value = 0.0, tolerance = 0.0;
  bool passed = false;
  std::string note;  // why it failed, or the tolerance's reason
};

std::vector<MetricComparison> compare_to_baseline(const nlohmann::ordered_json& baseline, const std::filesystem::path& run_dir);

// Markdown table of the comparison (for the CI artifact and the terminal).
std::string regression_report(const std::vector<MetricComparison>& results);

// A baseline from a run directory: every metric named in `rules` (per suite: metric -> tolerance,
// relative flag and reason) for every run of that suite.
nlohmann::ordered_json make_baseline(const std::filesystem::path& run_dir, const nlohmann::ordered_json& rules);

}  // namespace mrsph::verification
