// The transport-velocity shift's pair terms (transport_velocity.hpp), as an interaction for the pair
// sweeps, so that a schedule may run them beside another term of the same pairs
// (advection_pair_terms.hpp).
#pragma once

#include "fluid/fluid_body.hpp"

#include <vector>

namespace mrsph {

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

// 2 alpha h^2.
inline Real shift_coefficient(const FluidBody& fluid, Real alpha) { return 2.0 * alpha * fluid.h() * fluid.h(); }

// r_i += shift_i (computed from the unshifted positions, then applied).
void apply_shift(FluidParticles& f, const Vec2Array& shift);

}  // namespace mrsph
