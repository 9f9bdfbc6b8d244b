// Parallel loops over particles. Every loop body writes only to its own particle, so results do
// not depend on how TBB splits the range (deterministic for any thread count). Reductions used
// here (max) are exact, so they are deterministic too.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cstddef>
#include <limits>

namespace mrsph {

// Smallest chunk worth a task. A parallel loop costs microseconds to start, so a loop whose body
// visits neighbours (tens of pairs per particle) pays off from about a hundred particles, and a
// plain per-particle update only from a few thousand. A solid's loops outside its sub-steps (the
// fluid's force on it, its step criterion) run once per fluid step over a few hundred particles:
// on one thread below a thousand. Its sub-steps' loops, tens of thousands a run, go through a
// LoopTeam (core/loop_team.hpp) beside the fluid (run_side_by_side).
inline constexpr std::size_t kGrainNeighbourLoop = 128;
inline constexpr std::size_t kGrainSimpleLoop = 4096;
inline constexpr std::size_t kGrainSolidLoop = 1024;

// How a loop's range is shared among the threads.
enum class Sharing {
  Static,   // one contiguous block per thread: the least overhead, and each thread keeps the same
            // particles from one loop to the next
  Balanced  // blocks taken by whichever thread is free: for a loop that runs beside other work
};

template <class Body>
void parallel_for_each(std::size_t n, Body&& body, std::size_t grain = kGrainNeighbourLoop,
                       Sharing sharing = Sharing::Static) {
  if (n <= grain) {
    for (std::size_t i = 0; i < n; ++i) body(i);
    return;
  }
  const tbb::blocked_range<std::size_t> range(0, n, grain);
  const auto loop = [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) body(i);
  };
  if (sharing == Sharing::Balanced)
    tbb::parallel_for(range, loop, tbb::auto_partitioner());
  else
    tbb::parallel_for(range, loop, tbb::static_partitioner());
}

// A loop split into contiguous blocks, one task each: for a pass whose per-block partial results
// (histograms, bounds) are combined afterwards in block order, so the outcome does not depend on
// the number of blocks. At most one block per thread, each of at least `min_block` items.
inline std::size_t block_count(std::size_t n, std::size_t min_block) {
  const auto threads = static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
  return std::clamp<std::size_t>(n / std::max<std::size_t>(min_block, 1), 1, threads);
}

// Calls body(block, begin, end) for the `blocks` contiguous blocks of [0, n), in parallel.
template <class Body>
void for_each_block(std::size_t n, std::size_t blocks, Body&& body) {
  if (blocks <= 1) {
    body(std::size_t(0), std::size_t(0), n);
    return;
  }
  tbb::parallel_for(
      std::size_t(0), blocks, [&](std::size_t b) { body(b, n * b / blocks, n * (b + 1) / blocks); },
      tbb::static_partitioner());
}

// The lowest i in [0, n) for which found(i) holds, or n if none: where a serial scan would stop.
template <class Found>
std::size_t parallel_find_first(std::size_t n, Found&& found, std::size_t grain = kGrainSimpleLoop) {
  const auto scan = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      if (found(i)) return i;
    return n;
  };
  if (n <= grain) return scan(0, n);
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, grain), n,
      [&](const tbb::blocked_range<std::size_t>& r, std::size_t first) {
        return std::min(first, scan(r.begin(), r.end()));
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); }, tbb::static_partitioner());
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

// The largest value(i) over [0, n) and the lowest index that has it, as a serial scan that keeps the
// first strictly larger value finds them; NaN values are skipped. {lowest, n} when none is larger.
struct IndexedMax {
  double value;
  std::size_t index;
};
template <class Value>
IndexedMax parallel_indexed_max(std::size_t n, Value&& value, std::size_t grain = kGrainSimpleLoop) {
  const IndexedMax none{-std::numeric_limits<double>::infinity(), n};
  const auto scan = [&](std::size_t begin, std::size_t end, IndexedMax best) {
    for (std::size_t i = begin; i < end; ++i) {
      const double v = value(i);
      if (v > best.value) best = {v, i};
    }
    return best;
  };
  if (n <= grain) return scan(0, n, none);
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, grain), none,
      [&](const tbb::blocked_range<std::size_t>& r, IndexedMax best) { return scan(r.begin(), r.end(), best); },
      [](IndexedMax a, IndexedMax b) {
        return b.value > a.value || (b.value == a.value && b.index < a.index) ? b : a;
      },
      tbb::static_partitioner());
}

// Runs two independent pieces of work side by side: `shared`, whose loops take up whatever threads
// are free (Sharing::Balanced), and `single`, which starts on one thread (a solid's sub-steps, whose
// loop team takes helpers as they come free). Neither may read what the other writes. With one
// thread: `shared`, then `single`.
template <class Shared, class Single>
void run_side_by_side(Shared&& shared, Single&& single) {
  tbb::task_group group;
  group.run([&] { single(); });
  shared();
  group.wait();
}

}  // namespace mrsph
