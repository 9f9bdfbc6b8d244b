#pragma once

#include "suites/suite.hpp"

namespace mrsph::verification {

SuiteSummary run_speed_accuracy_suite(const SuiteContext& ctx);

}  // namespace mrsph::verification
