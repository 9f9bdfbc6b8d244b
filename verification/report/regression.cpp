#include "report/regression.hpp"

#include "core/json.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>

namespace mrsph::verification {

namespace {


std::optional<Json> read_summary(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    return Json::parse(in);
  } catch (const Json::exception&) {
    return std::nullopt;
  }
}

const Json* find_run(const Json& summary, const std::string& name) {
  for (const Json& run : summary.at("runs"))
    if (run.at("case").get<std::string>() == name) return &run;
  return nullptr;
}

}  // namespace

std::vector<MetricComparison> compare_to_baseline(const Json& baseline, const std::filesystem::path& run_dir) {
  std::vector<MetricComparison> out;
  for (auto suite = baseline.at("suites").begin(); suite != baseline.at("suites").end(); ++suite) {
    const auto summary = read_summary(run_dir / suite.key() / "summary.json");
    for (auto run = suite.value().begin(); run != suite.value().end(); ++run) {
      const Json* record = summary ? find_run(*summary, run.key()) : nullptr;
      for (auto metric = run.value().begin(); metric != run.value().end(); ++metric) {
        MetricComparison c;
        c.suite = suite.key();
        c.run = run.key();
        c.metric = metric.key();
        const Json& rule = metric.value();
        c.baseline = rule.at("value").get<double>();
        c.tolerance = std::max(rule.value("tolerance", 0.0), rule.value("relative", 0.0) * std::abs(c.baseline));
        c.note = rule.value("reason", "");
        if (!summary) {
          c.note = "no summary for suite " + suite.key();
        } else if (!record) {
          c.note = "run missing from the summary";
        } else if (record->value("diverged", false)) {
          c.note = "the run diverged";
        } else if (!record->at("metrics").contains(metric.key()) || record->at("metrics").at(metric.key()).is_null()) {
          c.note = "metric missing";
        } else {
          c.value = record->at("metrics").at(metric.key()).get<double>();
          c.passed = std::isfinite(c.value) && std::abs(c.value - c.baseline) <= c.tolerance;
        }
        out.push_back(std::move(c));
      }
    }
  }
  return out;
}

std::string regression_report(const std::vector<MetricComparison>& results) {
  std::string md = "| verdict | suite | run | metric | baseline | now | tolerance | note |\n|---|---|---|---|---|---|---|---|\n";
  int failed = 0;
  for (const MetricComparison& c : results) {
    failed += !c.passed;
    md += fmt::format("| {} | {} | {} | {} | {:.6g} | {:.6g} | {:.3g} | {} |\n", c.passed ? "ok" : "**REGRESSED**", c.suite,
                      c.run, c.metric, c.baseline, c.value, c.tolerance, c.note);
  }
  md += fmt::format("\n{} of {} metrics within tolerance of the baseline.\n", results.size() - failed, results.size());
  return md;
}

Json make_baseline(const std::filesystem::path& run_dir, const Json& rules) {
  Json baseline = {{"description", "metrics of the quick verification suites; regenerate with verify --write-baseline "
                                   "after an intended change, and say why in the commit"},
                   {"suites", Json::object()}};
  for (auto suite = rules.begin(); suite != rules.end(); ++suite) {
    const auto summary = read_summary(run_dir / suite.key() / "summary.json");
    if (!summary) throw std::runtime_error("no summary for suite '" + suite.key() + "' in " + run_dir.string());
    Json& suite_out = baseline["suites"][suite.key()];
    for (const Json& run : summary->at("runs")) {
      if (run.value("diverged", false)) continue;
      for (auto rule = suite.value().begin(); rule != suite.value().end(); ++rule) {
        const Json& metrics = run.at("metrics");
        if (!metrics.contains(rule.key()) || !metrics.at(rule.key()).is_number()) continue;
        Json entry = rule.value();
        entry["value"] = metrics.at(rule.key());
        suite_out[run.at("case").get<std::string>()][rule.key()] = entry;
      }
    }
  }
  return baseline;
}

}  // namespace mrsph::verification
