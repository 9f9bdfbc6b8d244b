#include "geometry/particle_normals.hpp"

#include "core/parallel.hpp"
#include "interaction/pair_sweep.hpp"

#include <algorithm>

namespace mrsph {

Vec2Array normals_from_kernel_gradient(const RealArray& vol, const NeighborList& inner) {
  Vec2Array normal(inner.size(), Vec2::Zero());
  parallel_for_each(inner.size(), [&](std::size_t a) {
    Vec2 gradient = Vec2::Zero();
    Real scale = 0.0;  // sum of |grad W| V: the gradient's size at a flat surface is a fraction of it
    for_each_pair(inner, a, [&](Index, const Neighbor& n) {
      gradient += (vol[n.j] * n.dW) * n.e;
      scale += vol[n.j] * std::abs(n.dW);
    });
    const Real norm = gradient.norm();
    if (norm > 1e-3 * scale) normal[a] = -gradient / norm;
  });
  return normal;
}

namespace {

// The lattice site one spacing out along a's normal is empty: a's pairs (e from the neighbour to a).
bool on_surface(const Vec2& n_a, const NeighborList& inner, std::size_t a, Real dp) {
  if (n_a == Vec2::Zero()) return false;
  bool empty = true;
  for_each_pair(inner, a, [&](Index, const Neighbor& n) {
    const Vec2 from_site = -n.r * Vec2(n.e) - dp * n_a;  // r_j - (r_a + dp n_a)
    if (from_site.squaredNorm() < 0.5625 * dp * dp) empty = false;  // (0.75 dp)^2
  });
  return empty;
}

}  // namespace

RealArray depths_below_surface(const Vec2Array& normal, const NeighborList& inner, Real dp, Real reach) {
  std::vector<char> surface(inner.size(), 0);
  parallel_for_each(inner.size(), [&](std::size_t a) { surface[a] = on_surface(normal[a], inner, a, dp); });
  RealArray depth(inner.size());
  parallel_for_each(inner.size(), [&](std::size_t a) {
    Real nearest = surface[a] ? 0.5 * dp : reach + 0.5 * dp;
    for_each_pair(inner, a, [&](Index, const Neighbor& n) {
      if (surface[n.j]) nearest = std::min(nearest, Vec2(n.r * Vec2(n.e) - 0.5 * dp * normal[n.j]).norm());
    });
    depth[a] = nearest;
  });
  return depth;
}

}  // namespace mrsph
