#pragma once

#include "suites/suite.hpp"

namespace mrsph::verification {

SuiteSummary run_fish_suite(const SuiteContext& ctx);

}  // namespace mrsph::verification
