// The paper's tables with this project's numbers beside them, in Markdown, from the summaries in a
// run directory: Table 2 (FSI2 cases I-IV: amplitude, frequency, CPU time) from turek-hron,
// Table 3 (FSI2 convergence of case III) from convergence, Table 5 (gate CPU times) from antoci.
// A table whose suite has not been run in that directory says so.
#pragma once

#include <filesystem>
#include <string>

namespace mrsph::verification {

std::string paper_tables(const std::filesystem::path& run_dir, const std::filesystem::path& project_dir);

}  // namespace mrsph::verification
