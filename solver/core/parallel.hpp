// Parallel loops over particles. Every loop body writes only to its own particle, so results do
// not depend on how TBB splits the range (deterministic for any thread count). Reductions used
// here (max, min) are exact, so they are deterministic too.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cstddef>
#include <limits>

namespace mrsph {

// Chunk size of the parallel loops. A body with at most this many particles runs serially: a
// parallel loop costs microseconds to start, more than a pass over a few hundred particles (the
// solid takes tens of sub-steps per acoustic step).
inline constexpr std::size_t kParallelGrain = 512;

template <class Body>
void parallel_for_each(std::size_t n, Body&& body) {
  if (n <= kParallelGrain) {
    for (std::size_t i = 0; i < n; ++i) body(i);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kParallelGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) body(i);
                    });
}

// Maximum of value(i) over [0, n); returns `lowest` for n == 0.
template <class Value>
double parallel_max(std::size_t n, Value&& value, double lowest = -std::numeric_limits<double>::infinity()) {
  if (n <= kParallelGrain) {
    double m = lowest;
    for (std::size_t i = 0; i < n; ++i) m = std::max(m, static_cast<double>(value(i)));
    return m;
  }
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, kParallelGrain), lowest,
      [&](const tbb::blocked_range<std::size_t>& r, double m) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) m = std::max(m, static_cast<double>(value(i)));
        return m;
      },
      [](double a, double b) { return std::max(a, b); });
}

}  // namespace mrsph
