#include "fluid/density_diffusion.hpp"

#include "core/parallel.hpp"

#include <cmath>

namespace mrsph {

void compute_renormalised_density_gradient(FluidBody& fluid, const NeighborList& inner) {
  if (fluid.options.delta_sph == 0.0) return;
  const FluidParticles& f = fluid.particles;
  fluid.density_gradient.resize(f.size());
  // A full support gives L^-1 = M1 I (0.974 at h = 1.3 dp); below a tenth of that squared, the
  // particle has lost most of its support and the inverse would amplify noise.
  constexpr Real kSmallestDeterminant = 0.01;
  parallel_for_each(f.size(), [&](std::size_t i) {
    Mat2 moment = Mat2::Zero();
    Vec2 difference = Vec2::Zero();
    for (const Neighbor& n : inner.of(i)) {
      const Vec2 grad = n.dW * n.e;
      moment -= (f.vol[n.j] * n.r) * (n.e * grad.transpose());  // sum V_j (r_j - r_i) (x) grad W
      difference += (f.vol[n.j] * (f.rho[n.j] - f.rho[i])) * grad;
    }
    const Real det = moment.determinant();
    fluid.density_gradient[i] = std::abs(det) < kSmallestDeterminant ? Vec2::Zero() : Vec2(moment.inverse() * difference);
  });
}

}  // namespace mrsph
