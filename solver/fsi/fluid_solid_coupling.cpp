#include "fsi/fluid_solid_coupling.hpp"

#include "core/parallel.hpp"
#include "interaction/pair_sweep.hpp"

#include <algorithm>

namespace mrsph {

namespace {

// An immersed boundary particle's share -V_a grad p_ref of a linear reference pressure (where
// FluidContact::reference_gradient is set).
Vec2 reference_share(const FluidContact& contact, std::size_t a) {
  return -(*contact.boundary.vol)[a] * *contact.reference_gradient;
}

}  // namespace

void set_force_from_fluid(const FluidContact& contact, SolidParticles& solid) {
  const bool has_viscous = !contact.pair_viscous_force.empty();
  parallel_for_each(solid.size(), [&](std::size_t a) {
    Vec2 force = contact.boundary_dissipation_reaction[a];
    if (contact.reference_gradient) force += reference_share(contact, a);
    for_each_pair_of_target(contact.pairs_of_boundary, a, [&](Index k) {
      force -= contact.pair_pressure_force[k];
      if (has_viscous) force -= contact.pair_viscous_force[k];
    });
    solid.force_prior[a] = force;
  }, kGrainSolidLoop);
}

Vec2 total_force_on_boundary(const FluidContact& contact) {
  Vec2 total = Vec2::Zero();
  for (const Vec2& f : contact.boundary_dissipation_reaction) total += f;
  if (contact.reference_gradient)
    for (std::size_t a = 0; a < contact.boundary.vol->size(); ++a) total += reference_share(contact, a);
  for (const Vec2& f : contact.pair_pressure_force) total -= f;
  for (const Vec2& f : contact.pair_viscous_force) total -= f;
  return total;
}

Vec2 viscous_force_on_boundary(const FluidContact& contact) {
  Vec2 total = Vec2::Zero();
  for (const Vec2& f : contact.pair_viscous_force) total -= f;
  return total;
}

void clear_boundary_impulses(std::vector<FluidContact>& contacts) {
  for (FluidContact& c : contacts) {
    c.recorded_impulse = Vec2::Zero();
    c.recorded_viscous_impulse = Vec2::Zero();
    c.recorded_duration = 0.0;
  }
}

void add_boundary_impulses(std::vector<FluidContact>& contacts, Real dt) {
  if (std::none_of(contacts.begin(), contacts.end(), [](const FluidContact& c) { return c.records_impulse; }))
    return;  // no force observer: nothing to sum, no tasks to start
  // Each contact's total and viscous force are serial sums over its pairs (their bits do not depend
  // on the thread count); the sums of all contacts run side by side.
  Vec2Array force(2 * contacts.size(), Vec2::Zero());
  parallel_for_each(force.size(), [&](std::size_t k) {
    const FluidContact& c = contacts[k / 2];
    if (c.records_impulse) force[k] = k % 2 == 0 ? total_force_on_boundary(c) : viscous_force_on_boundary(c);
  }, /*grain=*/1, Sharing::Balanced);
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    FluidContact& c = contacts[k];
    if (!c.records_impulse) continue;
    c.recorded_impulse += dt * force[2 * k];
    c.recorded_viscous_impulse += dt * force[2 * k + 1];
    c.recorded_duration += dt;
  }
}

Vec2 mean_force_on_boundary(const FluidContact& contact) {
  if (contact.records_impulse && contact.recorded_duration > 0.0)
    return contact.recorded_impulse / contact.recorded_duration;
  return total_force_on_boundary(contact);
}

Vec2 mean_viscous_force_on_boundary(const FluidContact& contact) {
  if (contact.records_impulse && contact.recorded_duration > 0.0)
    return contact.recorded_viscous_impulse / contact.recorded_duration;
  return viscous_force_on_boundary(contact);
}

void begin_kinematics_average(SolidParticles& solid) {
  parallel_for_each(solid.size(), [&](std::size_t a) {
    solid.pos_acoustic_start[a] = solid.pos[a];
    solid.vel_acoustic_start[a] = solid.vel[a];
  }, kGrainSimpleLoop);
}

void end_kinematics_average(SolidParticles& solid, Real dt, SolidKinematics mode) {
  parallel_for_each(solid.size(), [&](std::size_t a) {
    if (mode == SolidKinematics::Instantaneous) {
      solid.vel_ave[a] = solid.vel[a];
      solid.acc_ave[a] = solid.acc[a];
      return;
    }
    const Vec2 v_new = (solid.pos[a] - solid.pos_acoustic_start[a]) / dt;
    solid.acc_ave[a] = mode == SolidKinematics::Averaged ? Vec2((solid.vel[a] - solid.vel_acoustic_start[a]) / dt)
                                                         : Vec2((v_new - solid.vel_ave[a]) / dt);
    solid.vel_ave[a] = v_new;
  }, kGrainSimpleLoop);
}

}  // namespace mrsph
