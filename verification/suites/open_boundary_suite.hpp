// verify --suite open-boundaries: inlets and outlets (reports/open-boundaries.md).
//   Poiseuille flow driven by a pressure difference between a pressure inlet and a pressure outlet:
//     flow rate and profile against the analytic solution; the mass balance of the buffers
//   an acoustic pulse leaving through a pressure outlet: its reflection, fixed pressure (R = -1)
//     and weakly reflecting
//   the Turek & Hron channel in the benchmark's geometry (velocity inlet, pressure outlet): the
//     density during the inflow ramp; in full mode CFD2 and CFD3 drag, lift, St, and FSI2 case III
#pragma once

#include "suites/suite.hpp"

namespace mrsph::verification {

SuiteSummary run_open_boundary_suite(const SuiteContext& ctx);

}  // namespace mrsph::verification
