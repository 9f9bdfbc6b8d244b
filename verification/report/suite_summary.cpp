#include "report/suite_summary.hpp"

#include "io/atomic_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <thread>

namespace mrsph::verification {

SuiteSummary::SuiteSummary(std::string suite, bool quick, int threads)
    : suite_(std::move(suite)), quick_(quick), threads_(threads) {}

void SuiteSummary::check_near(const std::string& name, double value, double reference, double tolerance,
                              const std::string& source) {
  const bool ok = std::isfinite(value) && std::abs(value - reference) <= tolerance;
  checks_.push_back({{"name", name}, {"kind", "near"}, {"value", value}, {"reference", reference},
                     {"tolerance", tolerance}, {"passed", ok}, {"source", source}});
}

void SuiteSummary::check_at_most(const std::string& name, double value, double limit, const std::string& source) {
  const bool ok = std::isfinite(value) && value <= limit;
  checks_.push_back({{"name", name}, {"kind", "at_most"}, {"value", value}, {"reference", limit}, {"tolerance", 0.0},
                     {"passed", ok}, {"source", source}});
}

void SuiteSummary::check_range(const std::string& name, double value, double lower, double upper,
                               const std::string& source) {
  const bool ok = std::isfinite(value) && value >= lower && value <= upper;
  checks_.push_back({{"name", name}, {"kind", "range"}, {"value", value}, {"reference", 0.5 * (lower + upper)},
                     {"tolerance", 0.5 * (upper - lower)}, {"lower", lower}, {"upper", upper}, {"passed", ok},
                     {"source", source}});
}

void SuiteSummary::check_missing(const std::string& name, const std::string& why, const std::string& source) {
  checks_.push_back({{"name", name}, {"kind", "missing"}, {"value", nullptr}, {"reference", nullptr},
                     {"tolerance", nullptr}, {"passed", false}, {"source", source}, {"why", why}});
}

void SuiteSummary::note_skipped(const std::string& what, const std::string& why) {
  skipped_.push_back({{"what", what}, {"why", why}});
}

bool SuiteSummary::passed() const {
  for (const auto& c : checks_)
    if (!c.at("passed").get<bool>()) return false;
  return true;
}

Json SuiteSummary::to_json() const {
  Json j;
  j["suite"] = suite_;
  j["mode"] = quick_ ? "quick" : "full";
  j["passed"] = passed();
  j["machine"] = {{"threads", threads_}, {"hardware_concurrency", std::thread::hardware_concurrency()}};
  Json runs = Json::array();
  for (const SuiteRun& r : runs_) {
    Json run = {{"case", r.case_name}, {"config", r.config}, {"metrics", r.metrics}, {"cost", r.cost}};
    if (!r.compressibility.is_null()) run["compressibility"] = r.compressibility;
    run["diverged"] = r.diverged;
    run["divergence"] = r.divergence;
    runs.push_back(std::move(run));
  }
  j["runs"] = runs;
  j["checks"] = checks_;
  if (!skipped_.empty()) j["skipped"] = skipped_;
  for (auto it = extra_.begin(); it != extra_.end(); ++it) j[it.key()] = it.value();
  return j;
}

void SuiteSummary::write(const std::filesystem::path& dir) const {
  write_file_atomically(dir / "summary.json", to_json().dump(2) + "\n");
}

std::string SuiteSummary::checks_table() const {
  std::string out;
  for (const auto& c : checks_) {
    const bool ok = c.at("passed").get<bool>();
    std::string detail;
    const std::string kind = c.at("kind");
    if (kind == "missing") detail = "not evaluated: " + c.at("why").get<std::string>();
    else if (kind == "at_most") detail = fmt::format("{:.4g} <= {:.4g}", c.at("value").get<double>(), c.at("reference").get<double>());
    else if (kind == "range") detail = fmt::format("{:.4g} in [{:.4g}, {:.4g}]", c.at("value").get<double>(), c.at("lower").get<double>(), c.at("upper").get<double>());
    else detail = fmt::format("{:.4g} vs {:.4g} +/- {:.3g}", c.at("value").get<double>(), c.at("reference").get<double>(), c.at("tolerance").get<double>());
    out += fmt::format("  [{}] {}: {}\n", ok ? "pass" : "FAIL", c.at("name").get<std::string>(), detail);
  }
  for (const auto& s : skipped_)
    out += fmt::format("  [skip] {}: {}\n", s.at("what").get<std::string>(), s.at("why").get<std::string>());
  return out;
}

}  // namespace mrsph::verification
