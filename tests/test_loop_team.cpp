#include "core/loop_team.hpp"
#include "core/parallel.hpp"
#include "core/thread_limit.hpp"

#include <catch2/catch.hpp>

#include <tbb/task_group.h>

#include <atomic>
#include <limits>
#include <vector>

using namespace mrsph;

namespace {

// Runs many loops of different lengths through one team; every item of every loop must be visited
// exactly once, and each loop must see the previous one's writes (item i of loop k reads loop k - 1's).
void check_loops(int threads, std::size_t max_helpers) {
  run_with_threads(threads, [&] {
    std::vector<int> value(1000, 0);
    LoopTeam::run(max_helpers, [&](LoopTeam& team) {
      for (int loop = 1; loop <= 2000; ++loop) {
        const std::size_t n = static_cast<std::size_t>((loop * 37) % 1000) + 1;
        team.for_each(n, 7, [&](std::size_t i) { value[i] = value[i] == loop - 1 ? loop : -1; });
        for (std::size_t i = n; i < value.size(); ++i) value[i] = loop;  // the rest, by the leader
        const double m = team.max_over(n, 5, [&](std::size_t i) { return double(value[i] + int(i)); }, -1.0);
        REQUIRE(m == double(loop + int(n) - 1));
      }
    });
    for (int v : value) REQUIRE(v == 2000);
    return 0;
  });
}

}  // namespace

TEST_CASE("A loop team visits every item once and each loop after the previous one", "[parallel]") {
  SECTION("one thread: the leader alone") { check_loops(1, 3); }
  SECTION("two threads, one helper") { check_loops(2, 1); }
  SECTION("two threads, three helpers asked for (one can come)") { check_loops(2, 3); }
  SECTION("no helper allowed") { check_loops(2, 0); }
}

TEST_CASE("A loop team does not wait for a helper that cannot come", "[parallel]") {
  // Both threads of the arena busy: one leads the team, the other is held until the team is done.
  // The leader must finish alone, not wait for the helper it asked for.
  run_with_threads(2, [] {
    std::atomic<bool> team_done{false};
    std::vector<int> value(200, 0);
    tbb::task_group group;
    group.run([&] { while (!team_done.load()) {} });
    LoopTeam::run(1, [&](LoopTeam& team) {
      for (int loop = 0; loop < 100; ++loop) team.for_each(value.size(), 16, [&](std::size_t i) { ++value[i]; });
    });
    team_done = true;
    group.wait();
    for (int v : value) REQUIRE(v == 100);
    return 0;
  });
}

TEST_CASE("Parallel searches find what a serial scan finds, on any number of threads", "[parallel]") {
  // 10000 values with ties and NaNs: the first index holding the largest value (NaN skipped), and the
  // first index meeting a condition, as a serial scan from index 0 finds them.
  std::vector<double> v(10000);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<double>((i * 7919) % 1000);
  v[17] = std::numeric_limits<double>::quiet_NaN();
  v[9000] = std::numeric_limits<double>::quiet_NaN();
  for (int threads : {1, 2, 4}) {
    run_with_threads(threads, [&] {
      const IndexedMax m = parallel_indexed_max(v.size(), [&](std::size_t i) { return v[i]; }, 64);
      CHECK(m.value == 999.0);
      std::size_t first = 0;
      while (!(v[first] == 999.0)) ++first;
      CHECK(m.index == first);
      CHECK(parallel_find_first(v.size(), [&](std::size_t i) { return v[i] != v[i]; }, 64) == 17);
      CHECK(parallel_find_first(v.size(), [&](std::size_t i) { return v[i] > 1000.0; }, 64) == v.size());
      return 0;
    });
  }
}
