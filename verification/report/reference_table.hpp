// Reading reference data: numeric tables (whitespace- or comma-separated columns, an optional
// header line, blank lines ignored) and the project's typed-in JSON tables.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mrsph::verification {

struct NumericTable {
  std::vector<std::string> header;          // empty if the file has none
  std::vector<std::vector<double>> columns;
};

// Nothing if the file is missing; throws std::runtime_error naming the file and line if it is
// malformed (a row with a different number of columns, a non-numeric value).
std::optional<NumericTable> read_numeric_table(const std::filesystem::path& path);

// The project's typed-in reference data (reference-data/NAME); throws if missing or invalid.
nlohmann::json read_project_reference(const std::filesystem::path& project_dir, const std::string& name);

}  // namespace mrsph::verification
