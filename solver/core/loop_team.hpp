// A team for many small loops in a row (a solid's sub-steps: three loops over a few hundred
// particles, tens of thousands of times a run). A TBB loop of that size costs more to fork and join
// than its work (measured: FSI2's beam takes longer on two threads than on one); here the thread
// that leads keeps the loops' control flow, and threads that are free join it as helpers for as long
// as it leads, each loop's chunks claimed by whoever is there. A helper spins between loops, so a
// loop starts within a few hundred nanoseconds on every member.
//
// No one ever waits for a helper to arrive: with one thread, or with every other thread busy, the
// leader claims all the chunks itself. Results do not depend on who runs which chunk (each body
// writes only its own items; the max of max_over is exact).
#pragma once

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <thread>
#include <vector>

namespace mrsph {

class LoopTeam {
 public:
  // Runs lead(team) on the calling thread, with up to max_helpers free threads helping.
  template <class Lead>
  static void run(std::size_t max_helpers, Lead&& lead) {
    LoopTeam team;
    team.leader_ = std::this_thread::get_id();
    const std::size_t helpers =
        std::min<std::size_t>(max_helpers, static_cast<std::size_t>(std::max(0, tbb::this_task_arena::max_concurrency() - 1)));
    team.alone_ = helpers == 0;
    tbb::task_group group;
    for (std::size_t k = 0; k < helpers; ++k) group.run([&team] { team.help(); });
    try {
      lead(team);
    } catch (...) {
      team.finish(group);
      throw;
    }
    team.finish(group);
  }

  // body(i) for i in [0, n), in chunks of `chunk`; returns when all are done.
  template <class Body>
  void for_each(std::size_t n, std::size_t chunk, Body&& body) {
    run_loop(n, chunk, [&](std::size_t, std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) body(i);
    });
  }

  // The maximum of value(i) over [0, n) (lowest for n == 0); value(i) may update item i.
  template <class Value>
  double max_over(std::size_t n, std::size_t chunk, Value&& value, double lowest) {
    return max_over_each<1>(n, chunk, [&](std::size_t i) { return std::array<double, 1>{static_cast<double>(value(i))}; },
                            lowest)[0];
  }

  // The same for K values at once (value(i) returns std::array<double, K>), each maximised alone.
  template <std::size_t K, class Value>
  std::array<double, K> max_over_each(std::size_t n, std::size_t chunk, Value&& value, double lowest) {
    chunk = fitting_chunk(n, chunk);
    chunk_max_.assign(K * ((n + chunk - 1) / chunk), lowest);
    run_loop(n, chunk, [&](std::size_t c, std::size_t begin, std::size_t end) {
      std::array<double, K> m;
      m.fill(lowest);
      for (std::size_t i = begin; i < end; ++i) {
        const std::array<double, K> v = value(i);
        for (std::size_t k = 0; k < K; ++k) m[k] = std::max(m[k], v[k]);
      }
      std::copy(m.begin(), m.end(), chunk_max_.begin() + K * c);
    });
    std::array<double, K> m;
    m.fill(lowest);
    for (std::size_t j = 0; j < chunk_max_.size(); ++j) m[j % K] = std::max(m[j % K], chunk_max_[j]);
    return m;
  }

 private:
  using ChunkFn = void (*)(const void* body, std::size_t c, std::size_t begin, std::size_t end);

  LoopTeam() = default;

  // Publishes a loop, claims chunks beside the helpers, waits until every chunk is done.
  template <class ChunkBody>
  void run_loop(std::size_t n, std::size_t chunk, const ChunkBody& body) {
    chunk = fitting_chunk(n, chunk);
    const std::uint64_t chunks = (n + chunk - 1) / chunk;
    if (chunks == 0) return;
    if (alone_) {
      for (std::uint64_t c = 0; c < chunks; ++c) body(c, c * chunk, std::min(n, (c + 1) * chunk));
      return;
    }
    n_.store(n, std::memory_order_relaxed);
    chunk_.store(chunk, std::memory_order_relaxed);
    body_.store(&body, std::memory_order_relaxed);
    fn_.store([](const void* b, std::size_t c, std::size_t begin, std::size_t end) {
      (*static_cast<const ChunkBody*>(b))(c, begin, end);
    }, std::memory_order_relaxed);
    done_.store(0, std::memory_order_relaxed);
    const std::uint64_t loop = ++loops_ & ((std::uint64_t(1) << 24) - 1);
    claim_.store(loop << 40 | chunks, std::memory_order_release);  // makes the fields above visible
    run_chunks(loop, false);
    for (unsigned spins = 0; done_.load(std::memory_order_acquire) < chunks; ++spins) wait_a_little(spins);
  }

  // A chunk at least as large as asked for and large enough that the count fits the claim word.
  static std::size_t fitting_chunk(std::size_t n, std::size_t chunk) {
    return std::max<std::size_t>({chunk, 1, (n + kMask - 1) / kMask});
  }

  // Claims and runs chunks of loop `loop` until none is left (or a newer loop has started): the
  // leader from the front, helpers from the back, so that in a row of loops each thread tends to
  // get the same particles (they stay in its cache).
  void run_chunks(std::uint64_t loop, bool from_back) {
    for (;;) {
      std::uint64_t state = claim_.load(std::memory_order_acquire);
      if ((state >> 40) != loop) return;
      const std::uint64_t front = (state >> 20) & kMask, back = state & kMask;
      if (front >= back) return;
      const std::uint64_t next = from_back ? state - 1 : state + (std::uint64_t(1) << 20);
      if (!claim_.compare_exchange_weak(state, next, std::memory_order_acq_rel)) continue;
      const std::uint64_t c = from_back ? back - 1 : front;
      // Chunk c of this loop is ours: the leader waits for it, so the loop's fields stay valid.
      const std::size_t n = n_.load(std::memory_order_relaxed), chunk = chunk_.load(std::memory_order_relaxed);
      const std::size_t begin = c * chunk;
      fn_.load(std::memory_order_relaxed)(body_.load(std::memory_order_relaxed), c, begin, std::min(n, begin + chunk));
      done_.fetch_add(1, std::memory_order_release);
    }
  }

  void help() {
    // The leader can pick up its own helper task when it waits inside a TBB loop of its own: it
    // must not spin there for a stop that only it can give.
    if (std::this_thread::get_id() == leader_) return;
    std::uint64_t seen = 0;
    for (unsigned spins = 0; !stop_.load(std::memory_order_acquire);) {
      const std::uint64_t loop = claim_.load(std::memory_order_acquire) >> 40;
      if (loop != seen) {
        seen = loop;
        run_chunks(loop, true);
        spins = 0;
      } else {
        wait_a_little(spins++);
      }
    }
  }

  void finish(tbb::task_group& group) {
    stop_.store(true, std::memory_order_release);
    group.wait();
  }

  // A pause instruction between loops; after a few thousand (tens of microseconds), yield the core,
  // so that a helper on a machine with more threads than cores does not hold back the leader.
  static void wait_a_little(unsigned spins) {
#if defined(__x86_64__) || defined(__i386__)
    if (spins < 4096) {
      __builtin_ia32_pause();
      return;
    }
#endif
    std::this_thread::yield();
  }

  static constexpr std::uint64_t kMask = (1u << 20) - 1;
  std::atomic<std::uint64_t> claim_{0};  // loop number << 40 | first unclaimed chunk << 20 | end of the unclaimed
  std::atomic<std::uint64_t> done_{0};   // chunks of the current loop finished
  std::atomic<bool> stop_{false};
  std::atomic<std::size_t> n_{0}, chunk_{1};
  std::atomic<const void*> body_{nullptr};
  std::atomic<ChunkFn> fn_{nullptr};
  std::thread::id leader_;
  bool alone_ = false;             // no helper asked for: the loops run without claims
  std::uint64_t loops_ = 0;        // the leader's count of published loops
  std::vector<double> chunk_max_;  // max_over's per-chunk results (the leader's only)
};

}  // namespace mrsph
