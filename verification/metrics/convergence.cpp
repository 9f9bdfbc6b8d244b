#include "metrics/convergence.hpp"

#include <cmath>

namespace mrsph::verification {

std::optional<ConvergenceEstimate> three_grid_convergence(double coarse, double medium, double fine, double ratio) {
  const double d32 = coarse - medium, d21 = medium - fine;
  if (d21 == 0.0 || d32 == 0.0 || !(ratio > 1.0)) return std::nullopt;
  ConvergenceEstimate c;
  c.monotone = (d32 > 0.0) == (d21 > 0.0);
  c.observed_order = std::log(std::abs(d32 / d21)) / std::log(ratio);
  const double factor = std::pow(ratio, c.observed_order) - 1.0;
  c.extrapolated = fine + (fine - medium) / factor;
  c.gci = fine != 0.0 ? 1.25 * std::abs((fine - medium) / fine) / factor : 0.0;
  return c;
}

double order_from_errors(double error_coarse, double error_fine, double ratio) {
  return std::log(error_coarse / error_fine) / std::log(ratio);
}

void write_estimate(const ConvergenceEstimate& c, Json& row) {
  row["observed_order"] = c.observed_order;
  row["extrapolated"] = c.extrapolated;
  row["gci"] = c.gci;
  row["monotone"] = c.monotone;
}

}  // namespace mrsph::verification
