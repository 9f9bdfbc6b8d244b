#include "neighbor/cell_grid.hpp"

#include "core/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace mrsph {

CellGrid::CellGrid(const DomainBox& box, Real search_radius) : box_(box), search_radius_(search_radius) {
  if (!(search_radius > 0.0)) throw std::invalid_argument("CellGrid: search radius must be positive");
  for (int a = 0; a < 2; ++a) {
    if (!box_.periodic[a]) continue;
    const Real L = box_.length(a);
    if (!(L / search_radius <= kMaxPeriodicCells))
      throw std::invalid_argument("periodic length " + std::to_string(L) + " along axis " + std::to_string(a) +
                                  " is more than " + std::to_string(kMaxPeriodicCells) + " search radii");
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

namespace {

// Particles per block of the grid's parallel passes: a thousand particles are some microseconds of
// work, above what a task costs to start; fewer stay on one thread (a solid's grid, a contact's).
constexpr std::size_t kGrainGridBuild = 1024;

struct BlockBounds {
  Vec2 lo = Vec2::Constant(std::numeric_limits<Real>::infinity());
  Vec2 hi = Vec2::Constant(-std::numeric_limits<Real>::infinity());
};

}  // namespace

void CellGrid::build(const Vec2Array& positions) {
  const std::size_t blocks = block_count(positions.size(), kGrainGridBuild);
  wrap_and_size(positions, blocks);
  sort_by_cell(blocks);
}

// The wrapped positions, and along non-periodic axes a grid over their bounding box.
void CellGrid::wrap_and_size(const Vec2Array& positions, std::size_t blocks) {
  const std::size_t n = positions.size();
  wrapped_.resize(n);
  std::vector<BlockBounds> bounds(blocks);
  for_each_block(n, blocks, [&](std::size_t b, std::size_t begin, std::size_t end) {
    BlockBounds& bb = bounds[b];
    for (std::size_t i = begin; i < end; ++i) {
      const Vec2 p = box_.wrap(positions[i]);
      wrapped_[i] = p;
      for (int a = 0; a < 2; ++a) { bb.lo[a] = std::min(bb.lo[a], p[a]); bb.hi[a] = std::max(bb.hi[a], p[a]); }
    }
  });
  BlockBounds all;
  for (const BlockBounds& bb : bounds) {
    all.lo = all.lo.cwiseMin(bb.lo);
    all.hi = all.hi.cwiseMax(bb.hi);
  }
  for (int a = 0; a < 2; ++a) {
    if (box_.periodic[a]) continue;
    const Real lo = n > 0 ? all.lo[a] : 0.0, hi = n > 0 ? all.hi[a] : 0.0;
    // min and max skip a NaN, so only the first particle's NaN or an infinity fails here, as in the
    // serial scan from the first particle this replaced (the divergence checks name the particle).
    if ((n > 0 && std::isnan(wrapped_[0][a])) || !std::isfinite(lo) || !std::isfinite(hi))
      throw std::runtime_error("CellGrid: non-finite particle position");
    cell_size_[a] = search_radius_;
    origin_[a] = lo;
    const double span = (hi - lo) / search_radius_;
    if (span > 1e7) throw std::runtime_error("CellGrid: particles spread over more than 1e7 cells");
    cells_[a] = static_cast<int>(std::floor(span)) + 1;
  }
}

// A counting sort by cell, stable (particles of a cell in increasing index), in parallel blocks:
// each block counts its particles per cell, and block b's particles of cell c go after those of
// blocks before b, so the order is the serial sort's for any number of blocks.
void CellGrid::sort_by_cell(std::size_t blocks) {
  const std::size_t n = wrapped_.size(), ncell = static_cast<std::size_t>(cells_[0]) * cells_[1];
  std::vector<Index> cell_of(n);
  std::vector<std::vector<Index>> count(blocks, std::vector<Index>(ncell, 0));
  const CellRange empty{{{cells_[0], -1}, {cells_[1], -1}}};  // empty: no query is within reach
  std::vector<CellRange> occupied(blocks, empty);
  for_each_block(n, blocks, [&](std::size_t b, std::size_t begin, std::size_t end) {
    CellRange& occ = occupied[b];
    for (std::size_t i = begin; i < end; ++i) {
      const int cx = std::clamp(cell_coordinate(wrapped_[i][0], 0), 0, cells_[0] - 1);
      const int cy = std::clamp(cell_coordinate(wrapped_[i][1], 1), 0, cells_[1] - 1);
      cell_of[i] = cy * cells_[0] + cx;
      ++count[b][cell_of[i]];
      occ[0] = {std::min(occ[0][0], cx), std::max(occ[0][1], cx)};
      occ[1] = {std::min(occ[1][0], cy), std::max(occ[1][1], cy)};
    }
  });
  occupied_ = empty;
  for (const CellRange& occ : occupied)
    for (int a = 0; a < 2; ++a)
      occupied_[a] = {std::min(occupied_[a][0], occ[a][0]), std::max(occupied_[a][1], occ[a][1])};
  // Each block's count becomes the slot of its first particle in the cell.
  cell_start_.resize(ncell + 1);
  Index next = 0;
  for (std::size_t c = 0; c < ncell; ++c) {
    cell_start_[c] = next;
    for (std::size_t b = 0; b < blocks; ++b) next += std::exchange(count[b][c], next);
  }
  cell_start_[ncell] = next;
  sorted_.resize(n);
  sorted_x_.resize(n);
  sorted_y_.resize(n);
  for_each_block(n, blocks, [&](std::size_t b, std::size_t begin, std::size_t end) {
    std::vector<Index>& slot = count[b];
    for (std::size_t i = begin; i < end; ++i) {
      const Index k = slot[cell_of[i]]++;
      sorted_[k] = static_cast<Index>(i);
      sorted_x_[k] = wrapped_[i].x();
      sorted_y_[k] = wrapped_[i].y();
    }
  });
}

}  // namespace mrsph
