// Grid convergence (Roache 1998; Celik et al. 2008, J. Fluids Eng. 130:078001) for three solutions
// on grids refined by a constant ratio r (coarse -> fine: f3, f2, f1):
//   observed order      p = ln| (f3 - f2) / (f2 - f1) | / ln r
//   Richardson value    f_ext = f1 + (f1 - f2) / (r^p - 1)
//   GCI (fine grid)     1.25 |(f1 - f2) / f1| / (r^p - 1)      (safety factor 1.25 for 3 grids)
// With a known exact value, the order follows from the errors instead: p = ln(e_coarse / e_fine) / ln r.
#pragma once

#include "core/json.hpp"

#include <optional>

namespace mrsph::verification {

struct ConvergenceEstimate {
  double observed_order = 0.0;
  double extrapolated = 0.0;
  double gci = 0.0;           // relative, fine grid
  bool monotone = true;       // (f3 - f2) and (f2 - f1) of the same sign
};

// Nothing if the three values do not let an order be estimated (f2 == f1, or f2 == f3).
std::optional<ConvergenceEstimate> three_grid_convergence(double coarse, double medium, double fine, double ratio);

// The estimate into a table row, as observed_order, extrapolated, gci and monotone.
void write_estimate(const ConvergenceEstimate& c, Json& row);

double order_from_errors(double error_coarse, double error_fine, double ratio);

}  // namespace mrsph::verification
