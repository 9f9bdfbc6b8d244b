// Compressed-sparse-row neighbour lists with the kernel values cached per pair. Built once per
// advection step (fluid) or once in the reference configuration (solid), then reused: the cached
// geometry does not follow the particles during acoustic or solid sub-steps (dual-criteria time
// stepping, Zhang et al. 2020).
#pragma once

#include "core/types.hpp"
#include "kernel/wendland_c2.hpp"
#include "neighbor/cell_grid.hpp"

#include <span>
#include <vector>

namespace mrsph {

// One pair (i, j) seen from i: e points from j to i, r = |r_i - r_j|, W and dW = dW/dr at r.
struct Neighbor {
  Index j;
  Real r;
  Real W;
  Real dW;
  Vec2 e;
};

class NeighborList {
 public:
  std::size_t size() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
  std::size_t pair_count() const { return entries_.size(); }
  std::span<const Neighbor> of(std::size_t i) const {
    return {entries_.data() + offsets_[i], entries_.data() + offsets_[i + 1]};
  }
  Index offset(std::size_t i) const { return offsets_[i]; }
  const Neighbor& entry(std::size_t k) const { return entries_[k]; }

  // Neighbours of each query position among the particles of `target` within the kernel's
  // support. With `exclude_self`, the query set is the target set and the pair (i, i) is skipped
  // (its periodic images are kept).
  void build(const Vec2Array& queries, const CellGrid& target, const WendlandC2& kernel, bool exclude_self);

  // A pair accepted by the search, before its kernel values: j, |r_i - r_j|^2 and r_i - r_j.
  struct AcceptedPair {
    Index j;
    Real r2;
    Vec2 d;
  };

 private:
  std::vector<Index> offsets_;
  std::vector<Neighbor> entries_;
  std::vector<std::vector<AcceptedPair>> chunk_pairs_;  // reused between builds: no reallocation
};

// For a contact list query -> target, the entries of each target particle: target particle a owns
// the entries k in [offsets[a], offsets[a+1]) of `entries`, in increasing order of k. This lets a
// pair force computed once on the query side be summed, with the opposite sign, on the target side.
class TransposedContacts {
 public:
  void build(const NeighborList& list, std::size_t target_count);
  std::span<const Index> of(std::size_t a) const {
    return {entries_.data() + offsets_[a], entries_.data() + offsets_[a + 1]};
  }
  std::size_t size() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }

 private:
  std::vector<Index> offsets_;
  std::vector<Index> entries_;
};

}  // namespace mrsph
