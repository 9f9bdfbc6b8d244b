#include "neighbor/neighbor_list.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace mrsph {

void NeighborList::build(const Vec2Array& queries, const CellGrid& target, const WendlandC2& kernel,
                         bool exclude_self) {
  const std::size_t n = queries.size();
  const Real cutoff = kernel.cutoff();
  const Real cutoff2 = cutoff * cutoff;
  const DomainBox& box = target.box();

  // Fixed chunks, each filled by one task, then concatenated in order: one search pass and a
  // result independent of the thread count.
  constexpr std::size_t kChunk = 512;
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<std::vector<Neighbor>> chunk_entries(chunks);
  std::vector<Index> counts(n, 0);

  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
    auto& out = chunk_entries[c];
    out.clear();
    const std::size_t begin = c * kChunk, end = std::min(n, begin + kChunk);
    for (std::size_t i = begin; i < end; ++i) {
      const Vec2 xi = box.wrap(queries[i]);
      const std::size_t before = out.size();
      target.for_each_candidate(xi, [&](Index j, const Vec2& image) {
        // (xi - xj) - image is exactly antisymmetric in floating point: pair forces cancel to the bit.
        const Vec2 d = (xi - target.wrapped_position(j)) - image;
        const Real r2 = d.squaredNorm();
        if (r2 >= cutoff2) return;
        if (exclude_self && static_cast<std::size_t>(j) == i && image.isZero()) return;
        const Real r = std::sqrt(r2);
        // Coincident particles of different bodies: no direction; W counts, dW is zero at r = 0.
        const Vec2 e = r > 0.0 ? Vec2(d / r) : Vec2::Zero();
        out.push_back(Neighbor{j, r, kernel.W(r), kernel.dW(r), e});
      });
      // Order each particle's neighbours by index so the summation order (and the round-off) is
      // independent of the cell layout of the target.
      std::sort(out.begin() + before, out.end(), [](const Neighbor& a, const Neighbor& b) {
        return a.j != b.j ? a.j < b.j : a.e[0] < b.e[0];
      });
      counts[i] = static_cast<Index>(out.size() - before);
    }
  });

  offsets_.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) offsets_[i + 1] = offsets_[i] + counts[i];
  entries_.resize(offsets_[n]);
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
    std::copy(chunk_entries[c].begin(), chunk_entries[c].end(), entries_.begin() + offsets_[c * kChunk]);
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
