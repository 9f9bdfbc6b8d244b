// The pressure the fluid's pair forces are measured from (FluidOptions::pressure_reference):
// p_ref(x) = level + gradient . (x - origin). The pair forces use p - p_ref, and a gradient that is
// not zero is applied exactly, as the body force -V_i grad p_ref on each fluid particle and, on a
// boundary immersed in the fluid, -V_a grad p_ref on each of its particles (FluidContact).
// A pressure field that is a constant plus a linear function of x then exerts exactly its gradient,
// whatever the particles' arrangement, where the pair sum carries the arrangement's zero-order
// error times the field's value (reports/pressure.md sections 29 and 30).
#pragma once

#include "core/types.hpp"

namespace mrsph {

struct FluidBody;

struct ReferencePressure {
  Real level = 0.0;
  Vec2 gradient = Vec2::Zero();  // PressureReference::Linear only
  Vec2 origin = Vec2::Zero();
  Real at(const Vec2& x) const { return level + gradient.dot(x - origin); }
};

// Sets fluid.reference from the fluid's pressures eos(rho) (called after each density
// re-initialisation): Zero: 0; Mean: the mass-weighted mean; Linear: the least-squares fit
// p ~ level + gradient . (x - origin) over the particles in the domain (not the open boundaries'
// buffers), origin their centroid, along the axes that are not periodic (FluidBody::non_periodic_axes;
// across a periodic seam a linear field would jump) and that the particles span. Serial sums in
// particle order: runs stay bitwise reproducible.
void update_reference_pressure(FluidBody& fluid);

}  // namespace mrsph
