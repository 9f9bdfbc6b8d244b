#pragma once

#include "suites/suite.hpp"

namespace mrsph::verification {

SuiteSummary run_oscillating_plate_suite(const SuiteContext& ctx);

}  // namespace mrsph::verification
