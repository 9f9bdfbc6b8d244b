// Cell-linked list: particles binned into square cells of side >= the search radius, stored as a
// counting-sorted index array. A snapshot of (wrapped) positions is kept so a query never reads
// positions that moved after the build.
#pragma once

#include "core/types.hpp"
#include "neighbor/domain_box.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace mrsph {

class CellGrid {
 public:
  // The most cells along a periodic axis: far above any scene's (2e7 particles at most), and within
  // the int that indexes the cells.
  static constexpr Real kMaxPeriodicCells = 1.0e7;

  CellGrid(const DomainBox& box, Real search_radius);

  void build(const Vec2Array& positions);

  std::size_t size() const { return wrapped_.size(); }
  const Vec2& wrapped_position(Index j) const { return wrapped_[j]; }
  const DomainBox& box() const { return box_; }
  Real search_radius() const { return search_radius_; }

  // Calls f(begin, end, image) for the cells neighbouring the cell of `query` (a wrapped
  // position), row by row and from left to right: the particles are sorted_index(k) and
  // sorted_position(k) for k in [begin, end), and `image` is the periodic shift to add to their
  // positions. Neighbouring cells of one row with one image are contiguous in the sorted order, so
  // they come as one range (at most three ranges per row where the row wraps, one otherwise).
  template <class F>
  void for_each_run_near(const Vec2& query, F&& f) const {
    const int n = cells_[0];
    const int cx = cell_coordinate(query[0], 0), cy = cell_coordinate(query[1], 1);
    auto emit = [&](Index begin, Index end, Real shift_x, Real shift_y) {
      if (begin != end) f(begin, end, Vec2(shift_x, shift_y));
    };
    for (int dy = -1; dy <= 1; ++dy) {
      int row = cy + dy;
      Real shift_y = 0.0;
      if (!wrap_cell(row, 1, shift_y)) continue;
      const Index* start = cell_start_.data() + static_cast<std::size_t>(row) * n;  // start[n]: the row's end
      int first = cx - 1, last = cx + 1;
      if (!box_.periodic[0]) {
        first = std::max(first, 0);
        last = std::min(last, n - 1);
        if (first <= last) emit(start[first], start[last + 1], 0.0, shift_y);
        continue;
      }
      const Real L = box_.length(0);
      if (first < 0) {
        emit(start[n - 1], start[n], -L, shift_y);
        first = 0;
      }
      const bool wraps_right = last >= n;
      if (wraps_right) last = n - 1;
      emit(start[first], start[last + 1], 0.0, shift_y);
      if (wraps_right) emit(start[0], start[1], L, shift_y);
    }
  }
  // False if, along some axis, the query's cell is more than one cell away from the cells that hold
  // particles: no particle is within reach (a cheap test before the 3x3 stencil). Along a periodic
  // axis the grid spans the whole period, and a compact body away from the seam fills a few cells.
  bool within_reach(const Vec2& query) const {
    for (int a = 0; a < 2; ++a) {
      const int c = cell_coordinate(query[a], a);
      if (!box_.periodic[a]) {
        if (c < -1 || c > cells_[a]) return false;
        continue;
      }
      const int n = cells_[a];
      bool near = false;
      for (const int image : {c - n, c, c + n})
        near = near || (image >= occupied_[a][0] - 1 && image <= occupied_[a][1] + 1);
      if (!near) return false;
    }
    return true;
  }
  Index sorted_index(Index k) const { return sorted_[k]; }
  Vec2 sorted_position(Index k) const { return Vec2(sorted_x_[k], sorted_y_[k]); }
  // The same coordinates as separate arrays, for loops over a range that the compiler vectorises.
  const Real* sorted_x() const { return sorted_x_.data(); }
  const Real* sorted_y() const { return sorted_y_.data(); }

 private:
  using CellRange = std::array<std::array<int, 2>, 2>;  // per axis: the lowest and highest cell

  void wrap_and_size(const Vec2Array& positions, std::size_t blocks);
  void sort_by_cell(std::size_t blocks);
  int cell_coordinate(Real x, int axis) const {
    // floor() without the library call it is on the baseline x86-64 target; the same integer.
    const Real v = (x - origin_[axis]) / cell_size_[axis];
    int c = static_cast<int>(v);
    c -= static_cast<int>(static_cast<Real>(c) > v);
    if (box_.periodic[axis]) return std::clamp(c, 0, cells_[axis] - 1);  // x is wrapped already
    return c;  // may lie outside [0, n): wrap_cell() skips cells that do not exist
  }
  bool wrap_cell(int& c, int axis, Real& shift) const {
    const int n = cells_[axis];
    if (box_.periodic[axis]) {
      if (c < 0) { c += n; shift = -box_.length(axis); }
      else if (c >= n) { c -= n; shift = box_.length(axis); }
      return true;
    }
    return c >= 0 && c < n;
  }

  DomainBox box_;
  Real search_radius_;
  std::array<Real, 2> cell_size_{};
  std::array<Real, 2> origin_{};
  std::array<int, 2> cells_{};
  Vec2Array wrapped_;
  std::vector<Index> cell_start_;
  std::vector<Index> sorted_;
  RealArray sorted_x_, sorted_y_;  // wrapped positions in cell order, contiguous per cell
  CellRange occupied_{};  // the cells holding particles
};

}  // namespace mrsph
