// Parallel loops over particles. Every loop body writes only to its own particle, so results do
// not depend on how TBB splits the range (deterministic for any thread count). Reductions used
// here (max) are exact, so they are deterministic too.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <cstddef>
#include <limits>

namespace mrsph {

// Smallest chunk worth a task. A parallel loop costs microseconds to start, so a loop whose body
// visits neighbours (tens of pairs per particle) pays off from about a hundred particles, and a
// plain per-particle update only from a few thousand. The solid runs tens of sub-steps per
// acoustic step on a few hundred particles: the difference matters there.
inline constexpr std::size_t kGrainNeighbourLoop = 128;
inline constexpr std::size_t kGrainSimpleLoop = 4096;

template <class Body>
void parallel_for_each(std::size_t n, Body&& body, std::size_t grain = kGrainNeighbourLoop) {
  if (n <= grain) {
    for (std::size_t i = 0; i < n; ++i) body(i);
    return;
  }
  // Static partitioning: one contiguous block per thread, the least scheduling overhead for the
  // even work of particle loops.
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, n, grain),
      [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) body(i);
      },
      tbb::static_partitioner());
}

// Maximum of value(i) over [0, n); returns `lowest` for n == 0. value(i) may also update particle i.
template <class Value>
double parallel_max(std::size_t n, Value&& value, double lowest = -std::numeric_limits<double>::infinity(),
                    std::size_t grain = kGrainNeighbourLoop) {
  if (n <= grain) {
    double m = lowest;
    for (std::size_t i = 0; i < n; ++i) m = std::max(m, static_cast<double>(value(i)));
    return m;
  }
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, grain), lowest,
      [&](const tbb::blocked_range<std::size_t>& r, double m) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) m = std::max(m, static_cast<double>(value(i)));
        return m;
      },
      [](double a, double b) { return std::max(a, b); }, tbb::static_partitioner());
}

}  // namespace mrsph
