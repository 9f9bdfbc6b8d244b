// Exceptions raised by the solver. They are caught once, at the program's edge, and turned into
// a clear message and a non-zero exit. Physics code never prints.
#pragma once

#include <stdexcept>
#include <string>

namespace mrsph {

// Bad input: a scene file, an override or an option. The message names the file, the key
// (a JSON path such as "solids[0].material.poisson_ratio"), the value and what was expected.
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string key, std::string problem)
      : std::runtime_error(compose(file, key, problem)),
        file_(std::move(file)), key_(std::move(key)) {}
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }

 private:
  static std::string compose(const std::string& file, const std::string& key, const std::string& problem) {
    std::string where = file.empty() ? std::string() : file;
    if (!key.empty()) where += (where.empty() ? "" : ": ") + std::string("'") + key + "'";
    return where.empty() ? problem : where + ": " + problem;
  }
  std::string file_;
  std::string key_;
};

// A simulation that has left the physical regime: NaN/Inf, runaway velocity, a particle out of the
// domain, or an inverted solid element (J <= 0). Carries where and when it was detected.
struct DivergenceInfo {
  double time = 0.0;
  long long step = 0;        // advection step count when detected
  std::string body;
  long long particle = -1;
  std::string reason;        // e.g. "non-finite velocity", "|v| = 312 > 100 (10 c_F)"
};

class DivergenceError : public std::runtime_error {
 public:
  explicit DivergenceError(DivergenceInfo info)
      : std::runtime_error(describe(info)), info_(std::move(info)) {}
  const DivergenceInfo& info() const { return info_; }
  static std::string describe(const DivergenceInfo& d) {
    return "simulation diverged at t = " + std::to_string(d.time) + " (advection step " +
           std::to_string(d.step) + "), body '" + d.body + "', particle " + std::to_string(d.particle) +
           ": " + d.reason;
  }

 private:
  DivergenceInfo info_;
};

}  // namespace mrsph
