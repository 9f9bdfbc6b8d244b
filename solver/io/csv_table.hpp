// A numeric table written as CSV (header line, then rows; full double precision).
#pragma once

#include "core/types.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace mrsph {

struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  void add_row(std::vector<double> row) { rows.push_back(std::move(row)); }
  std::string to_string() const;
  void write(const std::filesystem::path& path) const;  // atomically
};

}  // namespace mrsph
