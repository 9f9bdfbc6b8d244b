// Cell-linked list: particles binned into square cells of side >= the search radius, stored as a
// counting-sorted index array. A snapshot of (wrapped) positions is kept so a query never reads
// positions that moved after the build.
#pragma once

#include "core/types.hpp"
#include "neighbor/domain_box.hpp"

#include <array>
#include <vector>

namespace mrsph {

class CellGrid {
 public:
  CellGrid(const DomainBox& box, Real search_radius);

  void build(const Vec2Array& positions);

  std::size_t size() const { return wrapped_.size(); }
  const Vec2& wrapped_position(Index j) const { return wrapped_[j]; }
  const DomainBox& box() const { return box_; }
  Real search_radius() const { return search_radius_; }

  // Calls f(begin, end, image) for each cell neighbouring the cell of `query` (a wrapped position):
  // the particles of that cell are sorted_index(k) and sorted_position(k) for k in [begin, end), and
  // `image` is the periodic shift to add to their positions.
  template <class F>
  void for_each_cell_near(const Vec2& query, F&& f) const {
    std::array<int, 2> c;
    for (int a = 0; a < 2; ++a) c[a] = cell_coordinate(query[a], a);
    for (int dy = -1; dy <= 1; ++dy) {
      int cy = c[1] + dy;
      Real shift_y = 0.0;
      if (!wrap_cell(cy, 1, shift_y)) continue;
      for (int dx = -1; dx <= 1; ++dx) {
        int cx = c[0] + dx;
        Real shift_x = 0.0;
        if (!wrap_cell(cx, 0, shift_x)) continue;
        const int cell = cy * cells_[0] + cx;
        if (cell_start_[cell] != cell_start_[cell + 1]) f(cell_start_[cell], cell_start_[cell + 1], Vec2(shift_x, shift_y));
      }
    }
  }
  // False if no cell within one cell of the query's holds particles' grid extent: the query point is
  // out of reach of every particle (a cheap test before the 3x3 stencil).
  bool within_reach(const Vec2& query) const {
    for (int a = 0; a < 2; ++a) {
      if (box_.periodic[a]) continue;
      const int c = cell_coordinate(query[a], a);
      if (c < -1 || c > cells_[a]) return false;
    }
    return true;
  }
  Index sorted_index(Index k) const { return sorted_[k]; }
  const Vec2& sorted_position(Index k) const { return sorted_pos_[k]; }

 private:
  int cell_coordinate(Real x, int axis) const;
  bool wrap_cell(int& c, int axis, Real& shift) const;

  DomainBox box_;
  Real search_radius_;
  std::array<Real, 2> cell_size_{};
  std::array<Real, 2> origin_{};
  std::array<int, 2> cells_{};
  Vec2Array wrapped_;
  std::vector<Index> cell_start_;
  std::vector<Index> sorted_;
  Vec2Array sorted_pos_;  // wrapped positions in cell order, contiguous per cell
};

}  // namespace mrsph
