#include "fluid/density_summation.hpp"

#include "core/parallel.hpp"

#include <algorithm>

namespace mrsph {

void reinitialise_density(FluidBody& fluid, const NeighborList& inner, const std::vector<FluidContact>& contacts) {
  FluidParticles& f = fluid.particles;
  const Real rho0 = fluid.material.rho0();
  const Real scale = rho0 / fluid.lattice_number_density;
  const Real W0 = fluid.kernel.W0();
  const bool free_surface = fluid.options.density == DensityReinitialisation::FreeSurface;
  parallel_for_each(f.size(), [&](std::size_t i) {
    const Real v0_i = f.mass[i] / rho0;
    Real sum = W0 * v0_i;
    for (const Neighbor& n : inner.of(i)) sum += n.W * f.mass[n.j] / rho0;
    for (const FluidContact& c : contacts) {
      const RealArray& vol = *c.boundary.vol;
      for (const Neighbor& n : c.pairs.of(i)) sum += n.W * vol[n.j];
    }
    Real rho = scale * sum / v0_i;
    if (free_surface) rho = std::max(rho, rho0);
    f.rho[i] = rho;
    f.vol[i] = f.mass[i] / rho;
  });
}

}  // namespace mrsph
