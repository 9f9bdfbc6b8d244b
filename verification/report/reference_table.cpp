#include "report/reference_table.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace mrsph::verification {

std::optional<NumericTable> read_numeric_table(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  NumericTable table;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    for (char& c : line)
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    std::istringstream words(line);
    std::vector<std::string> fields;
    for (std::string w; words >> w;) fields.push_back(w);
    if (fields.empty()) continue;
    std::vector<double> values;
    bool numeric = true;
    for (const std::string& f : fields) {
      char* end = nullptr;
      const double v = std::strtod(f.c_str(), &end);
      if (end == f.c_str() || *end != '\0') { numeric = false; break; }
      values.push_back(v);
    }
    if (!numeric) {
      if (table.columns.empty() && table.header.empty()) { table.header = fields; continue; }
      throw std::runtime_error(path.string() + ":" + std::to_string(line_number) + ": non-numeric value in '" + line + "'");
    }
    if (table.columns.empty()) table.columns.resize(values.size());
    if (values.size() != table.columns.size())
      throw std::runtime_error(path.string() + ":" + std::to_string(line_number) + ": expected " +
                               std::to_string(table.columns.size()) + " columns, found " + std::to_string(values.size()));
    for (std::size_t c = 0; c < values.size(); ++c) table.columns[c].push_back(values[c]);
  }
  return table;
}

nlohmann::json read_project_reference(const std::filesystem::path& project_dir, const std::string& name) {
  const std::filesystem::path path = project_dir / "reference-data" / name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("reference table " + path.string() + " is missing");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error("reference table " + path.string() + ": " + e.what());
  }
}

}  // namespace mrsph::verification
