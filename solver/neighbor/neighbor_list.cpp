#include "neighbor/neighbor_list.hpp"

#include "core/parallel.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace mrsph {

namespace {

using AcceptedPair = NeighborList::AcceptedPair;
using CandidateScratch = NeighborList::CandidateScratch;

// The candidates of query i (at xi) in one range [k_begin, k_end) of the target's sorted particles,
// shifted by `image`, appended to the query's scratch: their offsets (xi - x_k) - image, their
// squared distances (a loop the compiler vectorises) and their places k in the sorted order.
// (xi - xj) - image is exactly antisymmetric in floating point: pair forces cancel to the bit.
void append_candidates(const CellGrid& target, Index k_begin, Index k_end, const Vec2& image, const Vec2& xi,
                       CandidateScratch& scratch) {
  const std::size_t used = scratch.count, length = static_cast<std::size_t>(k_end - k_begin);
  if (scratch.r2.size() < used + length) scratch.resize(2 * (used + length));
  // The arrays never overlap (__restrict, which GCC and Clang accept): the loop is vectorised.
  const Real* __restrict x = target.sorted_x() + k_begin;
  const Real* __restrict y = target.sorted_y() + k_begin;
  Real* __restrict dx = scratch.dx.data() + used;
  Real* __restrict dy = scratch.dy.data() + used;
  Real* __restrict r2 = scratch.r2.data() + used;
  std::uint32_t* __restrict k = scratch.k.data() + used;
  const Real qx = xi.x(), qy = xi.y(), sx = image.x(), sy = image.y();
  for (std::size_t m = 0; m < length; ++m) {
    const Real ex = (qx - x[m]) - sx, ey = (qy - y[m]) - sy;
    dx[m] = ex;
    dy[m] = ey;
    r2[m] = ex * ex + ey * ey;
  }
  for (std::size_t m = 0; m < length; ++m) k[m] = static_cast<std::uint32_t>(k_begin + static_cast<Index>(m));
  scratch.count = used + length;
}

// Writes to out[used...] the query's candidates within the cutoff, in the order they were
// appended, without i itself where the query set is the target set (a particle meets itself only
// with a zero image: the stencil never visits a cell twice); returns the new end. About a third
// are kept, at random, so they are picked by advancing an end by 0 or 1, not by a branch.
std::size_t keep_within_cutoff(const CellGrid& target, std::size_t i, bool exclude_self, Real cutoff2,
                               CandidateScratch& scratch, std::vector<AcceptedPair>& out, std::size_t used) {
  const std::size_t length = scratch.count;
  if (out.size() < used + length) out.resize(2 * (used + length));  // only grows: sized once per build
  std::size_t count = 0;
  for (std::size_t m = 0; m < length; ++m) {
    scratch.kept[count] = static_cast<std::uint32_t>(m);
    count += static_cast<std::size_t>(scratch.r2[m] < cutoff2);
  }
  for (std::size_t a = 0; a < count; ++a) {
    const std::size_t m = scratch.kept[a];
    const Index j = target.sorted_index(static_cast<Index>(scratch.k[m]));
    if (exclude_self && static_cast<std::size_t>(j) == i) continue;
    out[used++] = AcceptedPair{j, scratch.r2[m], Vec2(scratch.dx[m], scratch.dy[m])};
  }
  return used;
}

}  // namespace

// Fixed chunks of queries, each searched by one task into its own list of accepted pairs; then the
// offsets, and each chunk's pairs get their kernel gradients as they are written to their place. The
// result is independent of the thread count. The order of a particle's neighbours follows the cell
// layout of the target, which depends only on the positions.
constexpr std::size_t kChunk = 256;

std::size_t NeighborList::search_chunk(const Vec2Array& queries, const ListRequest& request, std::size_t c,
                                       CandidateScratch& scratch, Index* counts) {
  const CellGrid& target = *request.target;
  const DomainBox& box = target.box();
  const Real cutoff2 = request.kernel.cutoff() * request.kernel.cutoff();
  std::size_t used = 0;
  const std::size_t begin = c * kChunk, end = std::min(queries.size(), begin + kChunk);
  for (std::size_t i = begin; i < end; ++i) {
    const Vec2 xi = box.wrap(queries[i]);
    if (!target.within_reach(xi)) continue;  // counts[i] stays 0
    const std::size_t before = used;
    scratch.count = 0;
    target.for_each_run_near(xi, [&](Index k_begin, Index k_end, const Vec2& image) {
      append_candidates(target, k_begin, k_end, image, xi, scratch);
    });
    used = keep_within_cutoff(target, i, request.exclude_self, cutoff2, scratch, chunk_pairs_[c], used);
    counts[i] = static_cast<Index>(used - before);
  }
  return used;
}

void NeighborList::fill_chunk(std::size_t c, std::size_t used) {
  Neighbor* to = entries_.data() + offsets_[c * kChunk];
  for (std::size_t m = 0; m < used; ++m) {
    const AcceptedPair& pair = chunk_pairs_[c][m];
    Neighbor& nb = *to++;
    nb.j = pair.j;
    nb.r = std::sqrt(pair.r2);
    Real w_not_stored;
    kernel_.values(nb.r, w_not_stored, nb.dW);
    // Coincident particles of different bodies: no direction; dW is zero at r = 0.
    nb.e = nb.r > 0.0 ? Vec2(pair.d * (1.0 / nb.r)) : Vec2::Zero();
  }
}

void NeighborList::build(const Vec2Array& queries, const CellGrid& target, const WendlandC2& kernel,
                         bool exclude_self) {
  const ListRequest request{this, &target, kernel, exclude_self};
  build_lists(queries, std::span<const ListRequest>(&request, 1));
}

void build_lists(const Vec2Array& queries, std::span<const ListRequest> requests) {
  const std::size_t n = queries.size(), lists = requests.size();
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<std::vector<Index>> counts(lists, std::vector<Index>(n, 0));
  std::vector<std::vector<std::size_t>> chunk_used(lists, std::vector<std::size_t>(chunks, 0));
  for (const ListRequest& request : requests) {
    request.list->kernel_ = request.kernel;
    if (request.list->chunk_pairs_.size() < chunks) request.list->chunk_pairs_.resize(chunks);
  }
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
    CandidateScratch scratch;
    for (std::size_t l = 0; l < lists; ++l)
      chunk_used[l][c] = requests[l].list->search_chunk(queries, requests[l], c, scratch, counts[l].data());
  });
  parallel_for_each(lists, [&](std::size_t l) {
    NeighborList& list = *requests[l].list;
    list.offsets_.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) list.offsets_[i + 1] = list.offsets_[i] + counts[l][i];
    list.entries_.resize(list.offsets_[n]);
  }, /*grain=*/1, Sharing::Balanced);
  tbb::parallel_for(std::size_t(0), chunks * lists, [&](std::size_t task) {
    const std::size_t l = task % lists, c = task / lists;
    requests[l].list->fill_chunk(c, chunk_used[l][c]);
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
