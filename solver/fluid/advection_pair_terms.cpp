#include "fluid/advection_pair_terms.hpp"

#include "fluid/shift_residue.hpp"
#include "fluid/transport_velocity.hpp"
#include "fluid/viscous_force.hpp"
#include "fluid/viscous_interaction.hpp"
#include "interaction/pair_sweep.hpp"

#include <limits>
#include <optional>

namespace mrsph {

void compute_viscous_force_and_transport_shift(FluidBody& fluid, const NeighborList& inner,
                                               std::vector<FluidContact>& contacts, const Vec2& body_acceleration) {
  const Real alpha = shift_alpha_per_step(fluid.options);
  std::optional<ViscousInteraction> viscous = prepare_viscous_interaction(fluid, contacts, body_acceleration);
  if (!viscous) return correct_transport_velocity(fluid, inner, contacts);
  if (alpha == 0.0) return sweep_with_contacts(inner, contacts, *viscous);

  FluidParticles& f = fluid.particles;
  Vec2Array shift(f.size(), Vec2::Zero());
  const ShiftResidue residue{f, contacts, shift, shift_coefficient(fluid, alpha), std::numeric_limits<Real>::infinity()};
  sweep_with_contacts(inner, contacts, Together<ViscousInteraction, ShiftResidue>{*viscous, residue});
  apply_shift(f, shift);
}

}  // namespace mrsph
