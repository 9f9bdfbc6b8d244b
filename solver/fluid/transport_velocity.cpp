#include "fluid/transport_velocity.hpp"

#include "core/parallel.hpp"

#include <limits>

namespace mrsph {

void correct_transport_velocity(FluidBody& fluid, const NeighborList& inner, const std::vector<FluidContact>& contacts) {
  const Real alpha = fluid.options.transport_velocity_alpha;
  if (alpha == 0.0) return;
  shift_towards_uniform_distribution(fluid, inner, contacts, alpha, std::numeric_limits<Real>::infinity());
}

void shift_towards_uniform_distribution(FluidBody& fluid, const NeighborList& inner,
                                        const std::vector<FluidContact>& contacts, Real alpha, Real max_shift) {
  FluidParticles& f = fluid.particles;
  const Real coefficient = 2.0 * alpha * fluid.h() * fluid.h();
  // Shifts are computed from the unshifted positions (cached geometry), then applied.
  Vec2Array shift(f.size());
  parallel_for_each(f.size(), [&](std::size_t i) {
    if (!f.in_domain(i)) {  // an open boundary's buffer: positions follow the imposed velocity
      shift[i] = Vec2::Zero();
      return;
    }
    Vec2 residue = Vec2::Zero();
    for (const Neighbor& n : inner.of(i)) residue += (f.vol[n.j] * n.dW) * n.e;
    for (const FluidContact& c : contacts) {
      const RealArray& vol = *c.boundary.vol;
      for (const Neighbor& n : c.pairs.of(i)) residue += (vol[n.j] * n.dW) * n.e;
    }
    shift[i] = -coefficient * residue;
    const Real length = shift[i].norm();
    if (length > max_shift) shift[i] *= max_shift / length;
  });
  parallel_for_each(f.size(), [&](std::size_t i) { f.pos[i] += shift[i]; }, kGrainSimpleLoop);
}

}  // namespace mrsph
