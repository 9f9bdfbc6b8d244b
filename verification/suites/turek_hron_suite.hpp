#pragma once

#include "suites/suite.hpp"
#include "sweep/sweep.hpp"

#include <optional>

namespace mrsph::verification {

// A case of the FSI2 benchmark (the paper's Table 1).
struct FsiCase {
  std::string name;
  int ratio;
  int resolution;
  std::string schedule;
  int sound_speed_factor = 10;  // c / U0; the scene's (the paper's) 10 adds no override
  std::optional<double> fluid_h_over_dp{};  // the fluid's smoothing length h / dp_F; the scene's (the paper's 1.3) if not given
};

// The sweep entry of a case: the overrides the turek-hron suite uses, so runs are shared.
SweepRun fsi2_sweep_run(const FsiCase& c, double end_time);

// Tip and force metrics of an FSI2 run from its observer series (statistics after `settle`).
Json fsi2_metrics(const ObserverSeries& tip, const ObserverSeries& forces, double end_time, double settle);

SuiteSummary run_turek_hron_suite(const SuiteContext& ctx);

}  // namespace mrsph::verification
