#include "suites/gate_experiment.hpp"

#include "metrics/signal_metrics.hpp"
#include "report/reference_table.hpp"

namespace mrsph::verification {

std::optional<Curve> read_reference_curve(const std::filesystem::path& path) {
  const auto table = read_numeric_table(path);
  if (!table || table->columns.size() < 2 || table->columns[0].empty()) return std::nullopt;
  Curve c;
  const double first = table->columns[1].front();
  for (std::size_t k = 0; k < table->columns[0].size(); ++k) {
    c.t.push_back(table->columns[0][k]);
    c.value.push_back(1000.0 * (table->columns[1][k] - first));
  }
  return c;
}

std::optional<Curve> gate_experiment_x(const SuiteContext& ctx) {
  if (!ctx.reference_dir) return std::nullopt;
  return read_reference_curve(*ctx.reference_dir / "antoci2007" / "Ex10X.txt");
}

Curve gate_tip_x_mm(const ObserverSeries& tip) {
  Curve x;
  x.t = tip.time;
  for (const auto& row : tip.values) x.value.push_back(-1000.0 * row[0]);
  return x;
}

std::optional<double> gate_rms_error_mm(const ObserverSeries& tip, const Curve& experiment) {
  const Curve x = gate_tip_x_mm(tip);
  if (const auto c = compare_curves(x.t, x.value, experiment.t, experiment.value)) return c->rms_error;
  return std::nullopt;
}

}  // namespace mrsph::verification
