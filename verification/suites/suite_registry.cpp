#include "suites/suite.hpp"
#include "suites/womersley_suite.hpp"

namespace mrsph::verification {

const std::vector<SuiteEntry>& registered_suites() {
  static const std::vector<SuiteEntry> suites{
      {"womersley", "periodic channel driven by an oscillating pressure gradient vs the analytic Womersley profile",
       run_womersley_suite},
  };
  return suites;
}

}  // namespace mrsph::verification
