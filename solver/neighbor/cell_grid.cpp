#include "neighbor/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mrsph {

CellGrid::CellGrid(const DomainBox& box, Real search_radius) : box_(box), search_radius_(search_radius) {
  if (!(search_radius > 0.0)) throw std::invalid_argument("CellGrid: search radius must be positive");
  for (int a = 0; a < 2; ++a) {
    if (!box_.periodic[a]) continue;
    const Real L = box_.length(a);
    const int n = static_cast<int>(std::floor(L / search_radius));
    // Three distinct cells are needed so that the 3x3 stencil never visits a cell twice.
    if (n < 3)
      throw std::invalid_argument("periodic length " + std::to_string(L) + " along axis " + std::to_string(a) +
                                  " must be at least 3 search radii (" + std::to_string(3 * search_radius) + ")");
    cells_[a] = n;
    cell_size_[a] = L / n;
    origin_[a] = box_.lower[a];
  }
}

void CellGrid::build(const Vec2Array& positions) {
  const std::size_t n = positions.size();
  wrapped_.resize(n);
  for (std::size_t i = 0; i < n; ++i) wrapped_[i] = box_.wrap(positions[i]);

  // Non-periodic axes: the grid spans the particles' bounding box.
  for (int a = 0; a < 2; ++a) {
    if (box_.periodic[a]) continue;
    Real lo = 0.0, hi = 0.0;
    if (n > 0) {
      lo = hi = wrapped_[0][a];
      for (const auto& p : wrapped_) { lo = std::min(lo, p[a]); hi = std::max(hi, p[a]); }
    }
    if (!std::isfinite(lo) || !std::isfinite(hi))
      throw std::runtime_error("CellGrid: non-finite particle position");
    cell_size_[a] = search_radius_;
    origin_[a] = lo;
    const double span = (hi - lo) / search_radius_;
    if (span > 1e7) throw std::runtime_error("CellGrid: particles spread over more than 1e7 cells");
    cells_[a] = static_cast<int>(std::floor(span)) + 1;
  }

  const std::size_t ncell = static_cast<std::size_t>(cells_[0]) * cells_[1];
  std::vector<Index> cell_of(n);
  cell_start_.assign(ncell + 1, 0);
  occupied_ = {{{cells_[0], -1}, {cells_[1], -1}}};  // empty: no query is within reach
  for (std::size_t i = 0; i < n; ++i) {
    const int cx = std::clamp(cell_coordinate(wrapped_[i][0], 0), 0, cells_[0] - 1);
    const int cy = std::clamp(cell_coordinate(wrapped_[i][1], 1), 0, cells_[1] - 1);
    cell_of[i] = cy * cells_[0] + cx;
    ++cell_start_[cell_of[i] + 1];
    occupied_[0] = {std::min(occupied_[0][0], cx), std::max(occupied_[0][1], cx)};
    occupied_[1] = {std::min(occupied_[1][0], cy), std::max(occupied_[1][1], cy)};
  }
  for (std::size_t c = 0; c < ncell; ++c) cell_start_[c + 1] += cell_start_[c];
  sorted_.resize(n);
  std::vector<Index> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) sorted_[fill[cell_of[i]]++] = static_cast<Index>(i);
  sorted_x_.resize(n);
  sorted_y_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    sorted_x_[k] = wrapped_[sorted_[k]].x();
    sorted_y_[k] = wrapped_[sorted_[k]].y();
  }
}

}  // namespace mrsph
