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

  // Calls f(j, image) for every particle j whose cell neighbours the cell of `query` (a wrapped
  // position); `image` is the periodic shift to add to wrapped_position(j).
  template <class F>
  void for_each_candidate(const Vec2& query, F&& f) const {
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
        const Vec2 image(shift_x, shift_y);
        const int cell = cy * cells_[0] + cx;
        for (Index k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) f(sorted_[k], image);
      }
    }
  }

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
};

}  // namespace mrsph
