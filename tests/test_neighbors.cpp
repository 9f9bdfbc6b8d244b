#include "neighbor/neighbor_list.hpp"
#include "core/thread_limit.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>

using namespace mrsph;

namespace {

Vec2Array random_points(std::size_t n, const Vec2& lo, const Vec2& hi, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y());
  Vec2Array p(n);
  for (auto& x : p) x = Vec2(ux(gen), uy(gen));
  return p;
}

// Brute force: every pair within the cutoff under the minimum-image convention.
std::map<std::pair<int, int>, double> brute_force(const Vec2Array& q, const Vec2Array& t, const DomainBox& box,
                                                  double cutoff, bool exclude_self) {
  std::map<std::pair<int, int>, double> pairs;
  for (std::size_t i = 0; i < q.size(); ++i)
    for (std::size_t j = 0; j < t.size(); ++j) {
      if (exclude_self && i == j) continue;
      const double r = box.difference(q[i], t[j]).norm();
      if (r < cutoff) pairs[{int(i), int(j)}] = r;
    }
  return pairs;
}

// The list of every pair of `points` (self excluded) with kernel k.
NeighborList inner_list(const Vec2Array& points, const DomainBox& box, const WendlandC2& k) {
  CellGrid grid(box, k.cutoff());
  grid.build(points);
  NeighborList list;
  list.build(points, grid, k, true);
  return list;
}

std::map<std::pair<int, int>, double> from_list(const NeighborList& list) {
  std::map<std::pair<int, int>, double> pairs;
  for (std::size_t i = 0; i < list.size(); ++i)
    for (const Neighbor& n : list.of(i)) pairs[{int(i), n.j}] = n.r;
  return pairs;
}

void compare(const std::map<std::pair<int, int>, double>& a, const std::map<std::pair<int, int>, double>& b) {
  REQUIRE(a.size() == b.size());
  for (const auto& [key, r] : a) {
    const auto it = b.find(key);
    REQUIRE(it != b.end());
    CHECK(it->second == Approx(r).margin(1e-12));
  }
}

}  // namespace

TEST_CASE("Cell-list neighbour search equals brute force", "[neighbors]") {
  const Vec2 lo(0.0, 0.0), hi(1.3, 0.9);
  for (bool periodic_x : {false, true})
    for (bool periodic_y : {false, true}) {
      DomainBox box{lo, hi, {periodic_x, periodic_y}};
      const Vec2Array fluid = random_points(700, lo, hi, 1);
      const Vec2Array solid = random_points(400, lo, hi, 2);
      const WendlandC2 k_fluid(0.04), k_solid(0.023);

      // Sections in a loop need names that differ per pass, or Catch runs them in the first pass only.
      const std::string axes = std::string(periodic_x ? "x" : "-") + (periodic_y ? "y" : "-") + " periodic";
      DYNAMIC_SECTION("inner, equal h, " << axes) {
        CellGrid grid(box, k_fluid.cutoff());
        grid.build(fluid);
        NeighborList list;
        list.build(fluid, grid, k_fluid, true);
        compare(brute_force(fluid, fluid, box, k_fluid.cutoff(), true), from_list(list));
      }
      DYNAMIC_SECTION("contact between different h uses the larger h, " << axes) {
        const WendlandC2 contact(std::max(k_fluid.h(), k_solid.h()));
        CellGrid grid(box, contact.cutoff());
        grid.build(solid);
        NeighborList list;
        list.build(fluid, grid, contact, false);
        compare(brute_force(fluid, solid, box, 2 * k_fluid.h(), false), from_list(list));
      }
      DYNAMIC_SECTION("contact with compact bodies: beside the periodic corner and in the middle, " << axes) {
        // A grid along a periodic axis spans the whole period; queries far from the cells a body
        // fills are skipped, and that skip must not lose pairs across the seam.
        for (const auto& [body_lo, body_hi] : {std::pair{Vec2(1.22, 0.82), Vec2(1.29, 0.89)},
                                               std::pair{Vec2(0.6, 0.4), Vec2(0.7, 0.5)}}) {
          const Vec2Array body = random_points(60, body_lo, body_hi, 3);
          CellGrid grid(box, k_fluid.cutoff());
          grid.build(body);
          NeighborList list;
          list.build(fluid, grid, k_fluid, false);
          const auto expected = brute_force(fluid, body, box, k_fluid.cutoff(), false);
          CHECK(expected.size() > 20);
          compare(expected, from_list(list));
        }
      }
    }
}

TEST_CASE("Cached pair geometry is exactly antisymmetric, also across periodic ends", "[neighbors]") {
  DomainBox box{Vec2(-2.0, 0.0), Vec2(1.0, 1.0), {true, false}};
  const Vec2Array p = random_points(500, box.lower, box.upper, 7);
  const WendlandC2 k(0.05);
  const NeighborList list = inner_list(p, box, k);
  std::map<std::pair<int, int>, Vec2> e;
  for (std::size_t i = 0; i < list.size(); ++i)
    for (const Neighbor& n : list.of(i)) e[{int(i), n.j}] = n.e * n.dW;
  for (const auto& [key, g] : e) {
    const auto it = e.find({key.second, key.first});
    REQUIRE(it != e.end());
    CHECK(it->second.x() == -g.x());  // bitwise, not approximately
    CHECK(it->second.y() == -g.y());
  }
}

TEST_CASE("Transposed contacts list every pair of each target once", "[neighbors]") {
  DomainBox box{Vec2(0, 0), Vec2(1, 1), {false, false}};
  const Vec2Array q = random_points(300, box.lower, box.upper, 3), t = random_points(200, box.lower, box.upper, 4);
  const WendlandC2 k(0.06);
  CellGrid grid(box, k.cutoff());
  grid.build(t);
  NeighborList list;
  list.build(q, grid, k, false);
  TransposedContacts tr;
  tr.build(list, t.size());
  std::size_t total = 0;
  for (std::size_t a = 0; a < t.size(); ++a)
    for (Index k_pair : tr.of(a)) {
      CHECK(list.entry(k_pair).j == Index(a));
      ++total;
    }
  CHECK(total == list.pair_count());
}

TEST_CASE("A listed pair moved since the build has the geometry of a list built at the new positions", "[neighbors]") {
  // Periodic along x, so that pairs across the seam keep their image: positions are not wrapped.
  DomainBox box{Vec2(0.0, 0.0), Vec2(1.0, 1.0), {true, false}};
  const Vec2Array p = random_points(400, box.lower, box.upper, 11);
  const WendlandC2 k(0.05);
  const NeighborList list = inner_list(p, box, k);
  const Vec2Array moved = random_points(p.size(), Vec2(-0.01, -0.01), Vec2(0.01, 0.01), 12);
  Vec2Array q(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) q[i] = box.wrap(p[i] + moved[i]);
  const NeighborList now = inner_list(q, box, k);
  std::map<std::pair<int, int>, Neighbor> rebuilt;
  for (std::size_t i = 0; i < now.size(); ++i)
    for (const Neighbor& n : now.of(i)) rebuilt[{int(i), n.j}] = n;
  std::size_t compared = 0;
  for (std::size_t i = 0; i < list.size(); ++i)
    for (const Neighbor& n : list.of(i)) {
      const MovedPair m = list.moved(n, moved[i], moved[n.j]);
      const auto it = rebuilt.find({int(i), n.j});
      if (it == rebuilt.end()) {  // left the support: no force
        CHECK(m.r >= k.cutoff() * (1.0 - 1e-12));
        CHECK(m.dW == 0.0);
        continue;
      }
      const Neighbor& fresh = it->second;
      CHECK(m.r == Approx(fresh.r).epsilon(1e-12));
      CHECK(m.dW == Approx(fresh.dW).epsilon(1e-9).margin(1e-9 * std::abs(k.dW(k.h()))));
      const Vec2 gradient = m.dW_over_r * m.r_ij, expected = fresh.dW * Vec2(fresh.e);
      CHECK((gradient - expected).norm() < 1e-9 * std::abs(k.dW(k.h())));
      const Neighbor entry = m.as_neighbor();
      CHECK((Vec2(entry.e) - Vec2(fresh.e)).norm() < 1e-12);
      ++compared;
    }
  CHECK(compared > 1000);
}

TEST_CASE("The cell grid sorts particles in the same order on any number of threads", "[neighbors][parallel]") {
  // 5000 particles in a channel periodic along x (the non-periodic y sized from the bounding box):
  // blocks of at least 1024 particles, so 1 to 4 blocks; each block's particles of a cell must go
  // after those of earlier blocks, as one serial stable counting sort puts them.
  DomainBox box;
  box.lower = Vec2(0.0, 0.0);
  box.upper = Vec2(6.0, 2.0);
  box.periodic = {true, false};
  const Vec2Array points = random_points(5000, Vec2(-0.5, 0.1), Vec2(6.5, 1.9), 11);
  auto order_on = [&](int threads) {
    std::vector<Index> order(points.size());
    run_with_threads(threads, [&] {
      CellGrid grid(box, 0.26);
      grid.build(points);
      for (std::size_t k = 0; k < order.size(); ++k) order[k] = grid.sorted_index(static_cast<Index>(k));
      return 0;
    });
    return order;
  };
  const std::vector<Index> serial = order_on(1);
  std::vector<Index> sorted = serial;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k < sorted.size(); ++k) REQUIRE(sorted[k] == static_cast<Index>(k));  // a permutation
  for (int threads : {2, 3, 8}) CHECK(order_on(threads) == serial);
}
