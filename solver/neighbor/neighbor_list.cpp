#include "neighbor/neighbor_list.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace mrsph {

void NeighborList::build(const Vec2Array& queries, const CellGrid& target, const WendlandC2& kernel,
                         bool exclude_self) {
  const std::size_t n = queries.size();
  const Real cutoff2 = kernel.cutoff() * kernel.cutoff();
  const DomainBox& box = target.box();

  // Fixed chunks, each filled by one task, then concatenated in order: one search pass and a
  // result independent of the thread count. The order of a particle's neighbours follows the cell
  // layout of the target, which depends only on the positions.
  constexpr std::size_t kChunk = 256;
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  if (chunk_entries_.size() < chunks) chunk_entries_.resize(chunks);
  std::vector<Index> counts(n, 0);

  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
    std::vector<Neighbor>& out = chunk_entries_[c];
    out.clear();
    const std::size_t begin = c * kChunk, end = std::min(n, begin + kChunk);
    for (std::size_t i = begin; i < end; ++i) {
      const Vec2 xi = box.wrap(queries[i]);
      if (!target.within_reach(xi)) continue;  // counts[i] stays 0
      const std::size_t before = out.size();
      // Pass 1: a tight distance filter that only records the accepted pairs. About a third of the
      // 3x3 cells' candidates lie within the cutoff, at random, so a branch on the test would be
      // mispredicted often: every candidate is written and kept by advancing the end by 0 or 1.
      target.for_each_cell_near(xi, [&](Index k_begin, Index k_end, const Vec2& image) {
        std::size_t used = out.size();
        out.resize(used + static_cast<std::size_t>(k_end - k_begin));
        const bool skip_self = exclude_self && image.isZero();
        for (Index k = k_begin; k < k_end; ++k) {
          // (xi - xj) - image is exactly antisymmetric in floating point: pair forces cancel to the bit.
          const Vec2 d = (xi - target.sorted_position(k)) - image;
          const Real r2 = d.squaredNorm();
          const Index j = target.sorted_index(k);
          const bool self = skip_self & (static_cast<std::size_t>(j) == i);
          out[used] = Neighbor{j, r2, 0.0, 0.0, d};
          used += static_cast<std::size_t>((r2 < cutoff2) & !self);
        }
        out.resize(used);
      });
      // Pass 2: kernel values of the accepted pairs.
      for (std::size_t m = before; m < out.size(); ++m) {
        Neighbor& nb = out[m];
        const Real r = std::sqrt(nb.r);
        nb.r = r;
        kernel.values(r, nb.W, nb.dW);
        // Coincident particles of different bodies: no direction; W counts, dW is zero at r = 0.
        nb.e = r > 0.0 ? Vec2(nb.e * (1.0 / r)) : Vec2::Zero();
      }
      counts[i] = static_cast<Index>(out.size() - before);
    }
  });

  offsets_.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) offsets_[i + 1] = offsets_[i] + counts[i];
  entries_.resize(offsets_[n]);
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
    std::copy(chunk_entries_[c].begin(), chunk_entries_[c].end(), entries_.begin() + offsets_[c * kChunk]);
  });
}

void TransposedContacts::build(const NeighborList& list, std::size_t target_count) {
  offsets_.assign(target_count + 1, 0);
  for (std::size_t k = 0; k < list.pair_count(); ++k) ++offsets_[list.entry(k).j + 1];
  for (std::size_t a = 0; a < target_count; ++a) offsets_[a + 1] += offsets_[a];
  entries_.resize(list.pair_count());
  std::vector<Index> fill(offsets_.begin(), offsets_.end() - 1);
  for (std::size_t k = 0; k < list.pair_count(); ++k) entries_[fill[list.entry(k).j]++] = static_cast<Index>(k);
}

}  // namespace mrsph
