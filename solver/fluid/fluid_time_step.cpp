#include "fluid/fluid_time_step.hpp"

#include "core/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace mrsph {

Real advection_time_step(const FluidBody& fluid, const Vec2& body_acceleration) {
  const FluidParticles& f = fluid.particles;
  const Real h = fluid.h();
  const Real speed2 = parallel_max(f.size(), [&](std::size_t i) {
    const Vec2 acc = f.dissipation_force[i] / f.mass[i] + body_acceleration;
    return std::max(f.vel[i].squaredNorm(), 4.0 * h * acc.norm());
  }, 0.0, kGrainSimpleLoop);
  const Real nu = fluid.material.viscosity / fluid.material.rho0();
  const Real speed = std::max({std::sqrt(speed2), fluid.options.reference_velocity, nu / h});
  return std::min(fluid.options.advection_cfl * h / speed, fluid.options.max_advection_step);
}

Real acoustic_time_step(const FluidBody& fluid) {
  const FluidParticles& f = fluid.particles;
  const Real vmax2 = parallel_max(f.size(), [&](std::size_t i) { return f.vel[i].squaredNorm(); }, 0.0, kGrainSimpleLoop);
  return fluid.options.acoustic_cfl * fluid.h() / (fluid.material.sound_speed() + std::sqrt(vmax2));
}

}  // namespace mrsph
