#include "observers/compressibility_monitor.hpp"

#include <cmath>

namespace mrsph {

void update_compressibility_record(const Simulation& sim, CompressibilityRecord& record) {
  if (!sim.has_fluid()) return;
  const FluidBody& fluid = sim.fluid();
  const FluidParticles& f = fluid.particles;
  const Real rho0 = fluid.material.rho0();
  const Real c0 = fluid.material.sound_speed();
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Real deviation = std::abs(f.rho[i] / rho0 - 1.0);
    if (deviation > record.density_deviation.value) record.density_deviation = {deviation, sim.time, f.pos[i]};
    const Real mach = f.vel[i].norm() / c0;
    if (mach > record.mach.value) record.mach = {mach, sim.time, f.pos[i]};
  }
}

}  // namespace mrsph
