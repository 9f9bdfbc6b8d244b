// report.md: the page a person reads first in a run directory. It is assembled from the suites'
// summary.json files (nothing is recomputed): what ran, on what machine, every check with value,
// reference, tolerance, verdict and source, every run with its metrics and cost, the figures.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace mrsph::verification {

struct ReportContext {
  std::string mode;            // quick | full
  int threads = 1;
  std::string command_line;
  std::string commit;          // git commit of the project, if known
};

std::string markdown_report(const std::filesystem::path& run_dir, const std::vector<std::string>& suites,
                            const ReportContext& context);

std::string machine_description();  // CPU model and hardware threads
std::string git_commit(const std::filesystem::path& project_dir);

}  // namespace mrsph::verification
