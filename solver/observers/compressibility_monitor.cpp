#include "observers/compressibility_monitor.hpp"

#include "core/parallel.hpp"

#include <cmath>

namespace mrsph {

void update_compressibility_record(const Simulation& sim, CompressibilityRecord& record) {
  if (!sim.has_fluid()) return;
  const FluidBody& fluid = sim.fluid();
  const FluidParticles& f = fluid.particles;
  const Real rho0 = fluid.material.rho0();
  const Real c0 = fluid.material.sound_speed();
  const IndexedMax deviation =
      parallel_indexed_max(f.size(), [&](std::size_t i) { return std::abs(f.rho[i] / rho0 - 1.0); });
  if (deviation.value > record.density_deviation.value)
    record.density_deviation = {deviation.value, sim.time, f.pos[deviation.index]};
  const IndexedMax mach = parallel_indexed_max(f.size(), [&](std::size_t i) { return f.vel[i].norm() / c0; });
  if (mach.value > record.mach.value) record.mach = {mach.value, sim.time, f.pos[mach.index]};
}

}  // namespace mrsph
