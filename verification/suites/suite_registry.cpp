#include "suites/suite.hpp"
#include "suites/antoci_suite.hpp"
#include "suites/momentum_suite.hpp"
#include "suites/oscillating_plate_suite.hpp"
#include "suites/turek_hron_suite.hpp"
#include "suites/womersley_suite.hpp"

namespace mrsph::verification {

const std::vector<SuiteEntry>& registered_suites() {
  static const std::vector<SuiteEntry> suites{
      {"womersley", "periodic channel driven by an oscillating pressure gradient vs the analytic Womersley profile",
       run_womersley_suite},
      {"oscillating-plate", "cantilever plate in its first bending mode vs Euler-Bernoulli; convergence, energy, nu = 0.49",
       run_oscillating_plate_suite},
      {"momentum", "closed FSI box: total momentum for position- and velocity-based Verlet, multi- and single-step",
       run_momentum_suite},
      {"turek-hron", "FSI2 beam behind a cylinder (Re 100): cases I-IV (+V) vs Turek-Hron and the paper's Table 2",
       run_turek_hron_suite},
      {"antoci", "dam break through an elastic gate vs the Antoci experiment, cases I-IV; dry-bed dam break",
       run_antoci_suite},
  };
  return suites;
}

}  // namespace mrsph::verification
