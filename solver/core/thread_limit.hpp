// Runs a program body on a given number of threads. A task arena, not tbb::global_control: with
// global_control active, every parallel_for with a static_partitioner leaks the proxy tasks the
// limited arena never runs (oneTBB issue #1403, present in Debian 12's 2021.8): a 2-second valve run
// grew to 17 GB. Inside an arena of the requested size the partitioner sees the right concurrency.
#pragma once

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <utility>

namespace mrsph {

// threads <= 0: all cores.
template <class Body>
int run_with_threads(int threads, Body&& body) {
  tbb::task_arena arena(threads > 0 ? threads : tbb::info::default_concurrency());
  return arena.execute(std::forward<Body>(body));
}

}  // namespace mrsph
