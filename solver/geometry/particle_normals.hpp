// Outward normals of a particle body from its own particles (the gradient of the colour function):
//   n_a = - sum_b V_b grad_a W_ab / | ... |
// Particles deep inside (vanishing gradient) get a zero normal; they are never within reach of
// another body. Works for any shape and across periodic images.
#pragma once

#include "core/types.hpp"
#include "neighbor/neighbor_list.hpp"

namespace mrsph {

Vec2Array normals_from_kernel_gradient(const RealArray& vol, const NeighborList& inner);

// Each particle's depth below the body's surface (the viscous wall rule, fluid/wall_rules.hpp), from
// the body's own particles: a particle with a normal lies on the surface if the lattice site one
// spacing dp out along its normal is empty (no particle within 0.75 dp of it); its surface point is
// half a spacing out. The depth is the distance to the nearest surface point within the kernel's
// reach (the list's cutoff; half a spacing for the surface particles), or the reach plus dp / 2
// where none is. Across periodic images too (the list's), so a periodic seam is not a surface, as a
// region's edge there would be.
RealArray depths_below_surface(const Vec2Array& normal, const NeighborList& inner, Real dp, Real reach);

}  // namespace mrsph
