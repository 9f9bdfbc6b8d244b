#include "fluid/transport_velocity.hpp"

#include "core/parallel.hpp"
#include "interaction/pair_sweep.hpp"

#include <limits>

namespace mrsph {

void correct_transport_velocity(FluidBody& fluid, const NeighborList& inner, const std::vector<FluidContact>& contacts) {
  const Real alpha = fluid.options.transport_velocity_alpha;
  if (alpha == 0.0) return;
  shift_towards_uniform_distribution(fluid, inner, contacts, alpha, std::numeric_limits<Real>::infinity());
}

namespace {

// The shift -2 alpha h^2 sum_j V_j dW_ij e_ij (fluid and boundary particles alike), its length capped.
struct ShiftResidue {
  struct Side {
    const RealArray& vol;
  };
  const FluidParticles& f;
  const std::vector<FluidContact>& contacts;
  Vec2Array& shift;
  Real coefficient, max_shift;

  // An open boundary's buffer: positions follow the imposed velocity (its shift stays zero).
  bool skips(std::size_t i) const { return !f.in_domain(i); }
  Vec2 begin(std::size_t) const { return Vec2::Zero(); }
  void inner(Vec2& residue, std::size_t, const Neighbor& n) const { residue += (f.vol[n.j] * n.dW) * n.e; }
  Side boundary(std::size_t c) const { return {*contacts[c].boundary.vol}; }
  void contact(Vec2& residue, std::size_t, const Side& b, Index, const Neighbor& n) const {
    residue += (b.vol[n.j] * n.dW) * n.e;
  }
  void finish(std::size_t i, const Vec2& residue) const {
    shift[i] = -coefficient * residue;
    const Real length = shift[i].norm();
    if (length > max_shift) shift[i] *= max_shift / length;
  }
};

}  // namespace

void shift_towards_uniform_distribution(FluidBody& fluid, const NeighborList& inner,
                                        const std::vector<FluidContact>& contacts, Real alpha, Real max_shift) {
  FluidParticles& f = fluid.particles;
  const Real coefficient = 2.0 * alpha * fluid.h() * fluid.h();
  // Shifts are computed from the unshifted positions (cached geometry), then applied.
  Vec2Array shift(f.size(), Vec2::Zero());
  sweep_with_contacts(inner, contacts, ShiftResidue{f, contacts, shift, coefficient, max_shift});
  parallel_for_each(f.size(), [&](std::size_t i) { f.pos[i] += shift[i]; }, kGrainSimpleLoop);
}

}  // namespace mrsph
