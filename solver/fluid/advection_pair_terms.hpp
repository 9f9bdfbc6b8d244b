// The pair terms of an advection step after the density summation (Algorithm 1): the viscous force
// (viscous_force.hpp) and the transport-velocity shift (transport_velocity.hpp). Both read the
// volumes the summation just set and the pairs as cached at the list build, and neither reads what
// the other writes (F^prior and the pair forces; the positions, shifted only after the sweep), so
// they run in one sweep over the pairs: the bits of the two sweeps they replace, for one pass over
// the entries. body_acceleration: b at the step's start, for the viscous force's quadratic wall rule.
#pragma once

#include "fluid/fluid_body.hpp"

namespace mrsph {

void compute_viscous_force_and_transport_shift(FluidBody& fluid, const NeighborList& inner,
                                               std::vector<FluidContact>& contacts, const Vec2& body_acceleration);

}  // namespace mrsph
