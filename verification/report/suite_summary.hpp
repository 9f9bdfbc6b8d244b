// The summary of one verification suite: the runs it made (configuration, metrics, cost), the
// checks with value / reference / tolerance / verdict / source, written as summary.json
// (VERIFICATION.md, "The summary contract"). Every check value comes from a run of this suite;
// every reference from a source outside it (a paper, an analytic solution, a benchmark).
#pragma once

#include "core/json.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace mrsph::verification {


struct SuiteRun {
  std::string case_name;
  Json config = Json::object();
  Json metrics = Json::object();
  Json cost = Json::object();
  Json compressibility;  // the fluid's largest density deviation and Mach number; null: no fluid
  bool diverged = false;
  Json divergence;  // null unless diverged
};

class SuiteSummary {
 public:
  SuiteSummary(std::string suite, bool quick, int threads);

  void add_run(SuiteRun run) { runs_.push_back(std::move(run)); }
  // |value - reference| <= tolerance
  void check_near(const std::string& name, double value, double reference, double tolerance, const std::string& source);
  // value <= limit
  void check_at_most(const std::string& name, double value, double limit, const std::string& source);
  // lower <= value <= upper
  void check_range(const std::string& name, double value, double lower, double upper, const std::string& source);
  // A check that could not be evaluated (a diverged run, a missing reference): recorded as failed.
  void check_missing(const std::string& name, const std::string& why, const std::string& source);
  // A comparison that was not made because its input is absent (a reference directory not given):
  // recorded and reported, but not counted as a failure.
  void note_skipped(const std::string& what, const std::string& why);

  bool passed() const;
  Json& extra() { return extra_; }  // suite-specific tables (e.g. the paper's tables)
  Json to_json() const;
  void write(const std::filesystem::path& dir) const;
  std::string checks_table() const;  // plain-text table for the terminal

 private:
  std::string suite_;
  bool quick_;
  int threads_;
  std::vector<SuiteRun> runs_;
  Json checks_ = Json::array();
  Json skipped_ = Json::array();
  Json extra_ = Json::object();
};

}  // namespace mrsph::verification
