// Compressed-sparse-row neighbour lists with the kernel gradients cached per pair. Built once per
// advection step (fluid) or once in the reference configuration (solid), then reused: the cached
// geometry does not follow the particles during acoustic or solid sub-steps (dual-criteria time
// stepping, Zhang et al. 2020).
#pragma once

#include "core/types.hpp"
#include "kernel/wendland_c2.hpp"
#include "neighbor/cell_grid.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace mrsph {

// One pair (i, j) seen from i: e points from j to i, r = |r_i - r_j|, dW = dW/dr at r. Every pass
// reads the entries, so they are kept small: W is not stored (NeighborList::W; only the density
// summation, once per advection step, needs it), and e is a Vec2 without Eigen's 16-byte
// alignment, which would pad an entry from 40 to 48 bytes (the arithmetic is the same).
using UnalignedVec2 = Eigen::Matrix<Real, 2, 1, Eigen::DontAlign>;
struct Neighbor {
  Index j;
  Real r;
  Real dW;
  UnalignedVec2 e;
};
static_assert(sizeof(Neighbor) == 40, "a neighbour entry is 40 bytes");

// A listed pair at positions other than the build's (NeighborList::moved): the kernel gradient is
// dW_over_r r_ij, which needs no division.
struct MovedPair {
  Index j;
  Real r, dW, dW_over_r;
  Vec2 r_ij;
  // As a neighbour entry (e = r_ij / r; two particles that met, r = 0, get e = 0 and have dW = 0).
  Neighbor as_neighbor() const { return {j, r, dW, UnalignedVec2(r_ij * (1.0 / std::max(r, std::numeric_limits<Real>::min())))}; }
};

class NeighborList;

// One list of a joint build (build_lists): the neighbours of the queries among `target`'s particles
// within the kernel's support; with `exclude_self` the query set is the target set and the pair
// (i, i) is skipped (its periodic images are kept).
struct ListRequest {
  NeighborList* list;
  const CellGrid* target;
  WendlandC2 kernel;
  bool exclude_self;
};

// Builds several lists of the same queries in one pass: each search task takes a chunk of queries
// for every list, so a fluid and its contacts cost two parallel loops in all instead of two each.
// Every list is the one NeighborList::build gives.
void build_lists(const Vec2Array& queries, std::span<const ListRequest> requests);

class NeighborList {
 public:
  std::size_t size() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
  std::size_t pair_count() const { return entries_.size(); }
  std::span<const Neighbor> of(std::size_t i) const {
    return {entries_.data() + offsets_[i], entries_.data() + offsets_[i + 1]};
  }
  Index offset(std::size_t i) const { return offsets_[i]; }
  const Neighbor& entry(std::size_t k) const { return entries_[k]; }

  // This list alone (ListRequest says what it holds).
  void build(const Vec2Array& queries, const CellGrid& target, const WendlandC2& kernel, bool exclude_self);

  // The pair after particle i moved by moved_i and j by moved_j since the build: r_ij, r, dW and dW / r
  // at the current positions, with the list's kernel (dW = 0 once the pair has left the support; a
  // pair that entered it since the build is not in the list). Position differences, so a pair
  // across a periodic boundary keeps its image (positions are wrapped only before a build).
  MovedPair moved(const Neighbor& n, const Vec2& moved_i, const Vec2& moved_j) const {
    const Vec2 r_ij = n.r * Vec2(n.e) + (moved_i - moved_j);
    const Real r = r_ij.norm();
    const Real dW_over_r = kernel_.dW_over_r(r);
    return {n.j, r, dW_over_r * r, dW_over_r, r_ij};
  }

  // W at the pair's distance, with the kernel the list was built with (the same bits as a stored W).
  Real W(const Neighbor& n) const {
    Real w, dw;
    kernel_.values(n.r, w, dw);
    return w;
  }

  // A pair accepted by the search, before its kernel values: j, |r_i - r_j|^2 and r_i - r_j.
  struct AcceptedPair {
    Index j;
    Real r2;
    Vec2 d;
  };
  // A search task's scratch: one query's candidates (offsets, squared distances, places in the
  // target's sorted order), and the indices of those within the cutoff.
  struct CandidateScratch {
    std::vector<Real> dx, dy, r2;
    std::vector<std::uint32_t> k, kept;
    std::size_t count = 0;
    void resize(std::size_t n) {
      dx.resize(n), dy.resize(n), r2.resize(n), k.resize(n), kept.resize(n);
    }
  };

 private:
  friend void build_lists(const Vec2Array& queries, std::span<const ListRequest> requests);
  // The accepted pairs of chunk c of the queries into chunk_pairs_[c] and their counts; returns how many.
  std::size_t search_chunk(const Vec2Array& queries, const ListRequest& request, std::size_t c,
                           CandidateScratch& scratch, Index* counts);
  // Chunk c's pairs to their place in entries_, with their kernel gradients.
  void fill_chunk(std::size_t c, std::size_t used);

  std::vector<Index> offsets_;
  std::vector<Neighbor> entries_;
  WendlandC2 kernel_{1.0};
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
