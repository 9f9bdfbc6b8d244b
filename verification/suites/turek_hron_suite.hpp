#pragma once

#include "suites/suite.hpp"

namespace mrsph::verification {

SuiteSummary run_turek_hron_suite(const SuiteContext& ctx);

}  // namespace mrsph::verification
