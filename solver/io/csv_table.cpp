#include "io/csv_table.hpp"

#include "io/atomic_file.hpp"

#include <fmt/format.h>

namespace mrsph {

std::string CsvTable::to_string() const {
  std::string out;
  for (std::size_t c = 0; c < columns.size(); ++c) out += (c ? "," : "") + columns[c];
  out += '\n';
  for (const auto& row : rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c) out += ',';
      out += fmt::format("{:.17g}", row[c]);
    }
    out += '\n';
  }
  return out;
}

void CsvTable::write(const std::filesystem::path& path) const { write_file_atomically(path, to_string()); }

}  // namespace mrsph
