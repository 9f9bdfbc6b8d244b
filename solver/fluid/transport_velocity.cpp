#include "fluid/transport_velocity.hpp"

#include "core/parallel.hpp"
#include "fluid/shift_residue.hpp"
#include "interaction/pair_sweep.hpp"

#include <algorithm>
#include <limits>

namespace mrsph {

Real shift_alpha_per_step(const FluidOptions& options) {
  return options.transport_velocity_alpha * options.paper_step_fraction();
}

void correct_transport_velocity(FluidBody& fluid, const NeighborList& inner, const std::vector<FluidContact>& contacts) {
  const Real alpha = shift_alpha_per_step(fluid.options);
  if (alpha == 0.0) return;
  shift_towards_uniform_distribution(fluid, inner, contacts, alpha, std::numeric_limits<Real>::infinity());
}

void shift_towards_uniform_distribution(FluidBody& fluid, const NeighborList& inner,
                                        const std::vector<FluidContact>& contacts, Real alpha, Real max_shift) {
  FluidParticles& f = fluid.particles;
  Vec2Array shift(f.size(), Vec2::Zero());
  sweep_with_contacts(inner, contacts, ShiftResidue{f, contacts, shift, shift_coefficient(fluid, alpha), max_shift});
  apply_shift(f, shift);
}

void apply_shift(FluidParticles& f, const Vec2Array& shift) {
  parallel_for_each(f.size(), [&](std::size_t i) { f.pos[i] += shift[i]; }, kGrainSimpleLoop);
}

}  // namespace mrsph
