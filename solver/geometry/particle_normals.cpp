#include "geometry/particle_normals.hpp"

#include "core/parallel.hpp"
#include "interaction/pair_sweep.hpp"

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

}  // namespace mrsph
