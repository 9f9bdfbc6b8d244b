#include "boundary/inflow.hpp"

#include "core/parallel.hpp"

#include <cmath>

namespace mrsph {

Real ParabolicInflowProfile::ramp(Real t) const {
  if (ramp_time <= 0.0 || t >= ramp_time) return 1.0;
  return 0.5 * (1.0 - std::cos(kPi * t / ramp_time));
}

Real ParabolicInflowProfile::ramp_rate(Real t) const {
  if (ramp_time <= 0.0 || t >= ramp_time || t < 0.0) return 0.0;
  return 0.5 * kPi / ramp_time * std::sin(kPi * t / ramp_time);
}

Vec2 ParabolicInflowProfile::velocity(const Vec2& p, Real t) const {
  const Real y = p.y() - channel_bottom;
  const Real H = channel_height;
  const Real u = 1.5 * mean_velocity * ramp(t) * 4.0 * y * (H - y) / (H * H);
  return Vec2(u, 0.0);
}

Vec2 inflow_velocity(const InflowProfile& profile, const Vec2& p, Real t) {
  return std::visit([&](const auto& prof) { return prof.velocity(p, t); }, profile);
}

Vec2 InflowBuffer::channel_acceleration(Real t) const {
  const auto* parabolic = std::get_if<ParabolicInflowProfile>(&profile);
  if (!drive_channel || parabolic == nullptr) return Vec2::Zero();
  return Vec2(parabolic->mean_velocity * parabolic->ramp_rate(t), 0.0);
}

void InflowBuffer::apply(FluidParticles& fluid, Real t, const DomainBox& box) const {
  // The region lies within its bounding box: most particles are ruled out without the region test.
  const BoundingBox bounds = region->bounds();
  parallel_for_each(fluid.size(), [&](std::size_t i) {
    const Vec2 p = box.wrap(fluid.pos[i]);
    const bool near = (p.array() >= bounds.lower.array()).all() && (p.array() <= bounds.upper.array()).all();
    if (near && region->contains(p)) fluid.vel[i] = inflow_velocity(profile, p, t);
  }, kGrainSimpleLoop);
}

}  // namespace mrsph
