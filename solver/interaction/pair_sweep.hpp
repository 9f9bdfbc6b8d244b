// The pair sweeps: the only code that knows how pairs are stored (the CSR lists of
// neighbor/neighbor_list.hpp, their transposes, and listed candidate pairs). Physics is written as
// small interaction structs that see one pair at a time; the sweeps below run them.
//
// A sweep over a fluid and its contacts (sweep_with_contacts) calls, for each particle i, inside one
// parallel loop and always in this order (so a particle's sums run in one order on any thread count):
//
//   if (op.skips(i)) done                                  (optional part)
//   auto sum = op.begin(i);
//   for each inner pair (i, j):                            op.inner(sum, i, pair)
//   op.after_inner(i, sum);                                (optional part)
//   for each contact c: auto side = op.boundary(c);        once per particle and contact
//     for each pair (i, a) of contact c, k its index:      op.contact(sum, i, side, k, pair)
//   op.finish(i, sum);
//
// k indexes per-pair storage (a boundary pair's force, kept for the boundary's reaction). A sweep over
// one list (sweep_pairs) calls begin, pair(sum, i, k, pair) and finish. The parts are inlined into the
// loop: no virtual call per pair. Where an interaction needs a particle's pairs inside a loop of its
// own (a solid's sub-step, two passes over a particle's pairs), for_each_pair visits them.
//
// That no other code iterates over pairs is checked by scripts/check_house.sh (its grep is in
// solver/README.md).
#pragma once

#include "core/parallel.hpp"
#include "neighbor/neighbor_list.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace mrsph {

// The per-particle visits below are forced inline into the sweep's loop: left to itself GCC kept
// visit_with_contacts a call per particle, and the interaction's loads were not hoisted out of
// its pair loops (FSI2 6 % slower on one thread than the hand-written loops this replaced).
#if defined(__GNUC__)
#define MRSPH_INLINE_VISIT inline __attribute__((always_inline))
#else
#define MRSPH_INLINE_VISIT inline
#endif

// fn(k, pair) for each pair of particle i in `list`, in the list's order.
template <class Fn>
MRSPH_INLINE_VISIT void for_each_pair(const NeighborList& list, std::size_t i, Fn&& fn) {
  const Index end = list.offset(i + 1);
  for (Index k = list.offset(i); k < end; ++k) fn(k, list.entry(k));
}

// fn(k) for each pair index of particle i: for interactions that keep compact per-pair arrays of
// their own (a solid's neighbour indices and gradient weights) and do not read the cached entries.
template <class Fn>
MRSPH_INLINE_VISIT void for_each_pair_index(const NeighborList& list, std::size_t i, Fn&& fn) {
  const Index end = list.offset(i + 1);
  for (Index k = list.offset(i); k < end; ++k) fn(k);
}

// The index k of the pair (i, j) in `list`, or -1 if j is not a neighbour of i.
inline long pair_index(const NeighborList& list, std::size_t i, Index j) {
  const Index end = list.offset(i + 1);
  for (Index k = list.offset(i); k < end; ++k)
    if (list.entry(k).j == j) return static_cast<long>(k);
  return -1;
}

// The neighbour j of every pair, in pair order.
inline std::vector<Index> pair_neighbors(const NeighborList& list) {
  std::vector<Index> j(list.pair_count());
  for (std::size_t k = 0; k < list.pair_count(); ++k) j[k] = list.entry(k).j;
  return j;
}

// fn(k) for each pair k of a contact list that has boundary particle a as its target (increasing k).
template <class Fn>
inline void for_each_pair_of_target(const TransposedContacts& transposed, std::size_t a, Fn&& fn) {
  for (Index k : transposed.of(a)) fn(k);
}

// fn(a, b) for each listed pair, in the list's order (serial: solid contacts, a few hundred pairs).
template <class Fn>
inline void for_each_listed_pair(const std::vector<std::pair<Index, Index>>& pairs, Fn&& fn) {
  for (const auto& [a, b] : pairs) fn(a, b);
}

// The pairs (i, j) with i a query position and j a particle of `target`'s grid closer than `radius`,
// that both filters accept, in increasing order (a contact's candidate list; serial). The grid must
// not be periodic: positions are compared as they are.
template <class QueryFilter, class TargetFilter>
void list_pairs_within(const Vec2Array& queries, const CellGrid& target, Real radius, QueryFilter&& query_ok,
                       TargetFilter&& target_ok, std::vector<std::pair<Index, Index>>& pairs) {
  pairs.clear();
  for (std::size_t i = 0; i < queries.size(); ++i) {
    if (!query_ok(i) || !target.within_reach(queries[i])) continue;
    target.for_each_run_near(queries[i], [&](Index begin, Index end, const Vec2&) {
      for (Index k = begin; k < end; ++k)
        if ((queries[i] - target.sorted_position(k)).squaredNorm() < radius * radius && target_ok(target.sorted_index(k)))
          pairs.emplace_back(static_cast<Index>(i), target.sorted_index(k));
    });
  }
  std::sort(pairs.begin(), pairs.end());
}

// The parallel sweep over one list: begin, pair for each pair, finish (see above).
template <class Op>
void sweep_pairs(const NeighborList& list, Op&& op) {
  parallel_for_each(list.size(), [&](std::size_t i) {
    auto sum = op.begin(i);
    for_each_pair(list, i, [&](Index k, const Neighbor& n) { op.pair(sum, i, k, n); });
    op.finish(i, sum);
  });
}

// One particle's pairs with its inner neighbours and with every contact's boundary particles, in the
// order of the header: for interactions evaluated one particle at a time inside another loop.
template <class Op, class Contacts, class Sum>
MRSPH_INLINE_VISIT void visit_with_contacts(const NeighborList& inner, Contacts& contacts, std::size_t i, Op& op, Sum& sum) {
  for_each_pair(inner, i, [&](Index, const Neighbor& n) { op.inner(sum, i, n); });
  if constexpr (requires { op.after_inner(i, sum); }) op.after_inner(i, sum);
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const auto side = op.boundary(c);
    for_each_pair(contacts[c].pairs, i, [&](Index k, const Neighbor& n) { op.contact(sum, i, side, k, n); });
  }
}

// Two interactions of the same pairs in one sweep (sweep_with_contacts(inner, contacts,
// Together<A, B>{a, b})): each keeps its own sum and sees the pairs in the order of the header, so
// both give the bits they give alone, for one pass over the entries instead of two. A particle that
// one of them skips is visited for the other; the skipping one's sum is dropped, not finished.
template <class A, class B>
struct Together {
  A a;
  B b;
  template <class Op>
  static bool skipped(const Op& op, std::size_t i) {
    if constexpr (requires { op.skips(i); }) return op.skips(i);
    else return false;
  }
  template <class Op, class Sum>
  static void after_inner_of(const Op& op, std::size_t i, Sum& sum) {
    if constexpr (requires { op.after_inner(i, sum); }) op.after_inner(i, sum);
  }
  struct Sum {
    decltype(std::declval<const A&>().begin(0)) a;
    decltype(std::declval<const B&>().begin(0)) b;
  };
  struct Side {
    decltype(std::declval<const A&>().boundary(0)) a;
    decltype(std::declval<const B&>().boundary(0)) b;
  };
  Sum begin(std::size_t i) const { return {a.begin(i), b.begin(i)}; }
  MRSPH_INLINE_VISIT void inner(Sum& s, std::size_t i, const Neighbor& n) const {
    a.inner(s.a, i, n);
    b.inner(s.b, i, n);
  }
  void after_inner(std::size_t i, Sum& s) const {
    after_inner_of(a, i, s.a);
    after_inner_of(b, i, s.b);
  }
  Side boundary(std::size_t c) const { return {a.boundary(c), b.boundary(c)}; }
  MRSPH_INLINE_VISIT void contact(Sum& s, std::size_t i, const Side& side, Index k, const Neighbor& n) const {
    a.contact(s.a, i, side.a, k, n);
    b.contact(s.b, i, side.b, k, n);
  }
  void finish(std::size_t i, const Sum& s) const {
    if (!skipped(a, i)) a.finish(i, s.a);
    if (!skipped(b, i)) b.finish(i, s.b);
  }
};

// The parallel sweep over a fluid's inner list and its contacts (`contacts`: a range of structs with
// a NeighborList `pairs`, fluid particle -> boundary particle).
template <class Op, class Contacts>
void sweep_with_contacts(const NeighborList& inner, Contacts& contacts, Op&& op, Sharing sharing = Sharing::Static) {
  parallel_for_each(inner.size(), [&](std::size_t i) {
    if constexpr (requires { op.skips(i); })
      if (op.skips(i)) return;
    auto sum = op.begin(i);
    visit_with_contacts(inner, contacts, i, op, sum);
    op.finish(i, sum);
  }, kGrainNeighbourLoop, sharing);
}

}  // namespace mrsph
