// Outward normals of a particle body from its own particles (the gradient of the colour function):
//   n_a = - sum_b V_b grad_a W_ab / | ... |
// Particles deep inside (vanishing gradient) get a zero normal; they are never within reach of
// another body. Works for any shape and across periodic images.
#pragma once

#include "core/types.hpp"
#include "neighbor/neighbor_list.hpp"

namespace mrsph {

Vec2Array normals_from_kernel_gradient(const RealArray& vol, const NeighborList& inner);

}  // namespace mrsph
