// The elastic gate's experiment (Antoci et al. 2007) as the suites compare with it: curves in mm
// with their first sample subtracted (a digitisation offset, PROVENANCE.md in the reference data),
// the gate's free-end x positive downstream (towards -x in the scene's layout).
#pragma once

#include "run/runner.hpp"
#include "suites/suite.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace mrsph::verification {

struct Curve {
  std::vector<double> t, value;
};

// An Antoci-format curve (t [s], displacement [m]) in mm with the first sample subtracted; nothing if
// the file is missing or has fewer than two columns.
std::optional<Curve> read_reference_curve(const std::filesystem::path& path);

// The experiment's horizontal curve (Ex10X.txt) from --reference-dir; nothing without it.
std::optional<Curve> gate_experiment_x(const SuiteContext& ctx);

// The free end's downstream displacement [mm] from the gate_tip observer (column 0: dx [m]).
Curve gate_tip_x_mm(const ObserverSeries& tip);

// RMS error of the free end's x against the experiment at its times [mm]; nothing if they do not overlap.
std::optional<double> gate_rms_error_mm(const ObserverSeries& tip, const Curve& experiment);

}  // namespace mrsph::verification
