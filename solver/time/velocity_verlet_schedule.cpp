#include "time/velocity_verlet_schedule.hpp"

#include "fluid/acoustic_step.hpp"
#include "fluid/advection_pair_terms.hpp"
#include "fluid/density_summation.hpp"
#include "fluid/fluid_time_step.hpp"
#include "fsi/fluid_solid_coupling.hpp"
#include "solid/solid_dynamics.hpp"
#include "core/step_splitting.hpp"

#include <algorithm>
#include <stdexcept>

namespace mrsph {

namespace {

void integrate_solid_velocity_verlet(SolidBody& solid, const Simulation& sim, Real t, Real dt, long long& count) {
  Real elapsed = 0.0;
  for (bool last = false; !last;) {
    const SplitStep step = split_remaining(dt - elapsed, solid_time_step(solid));
    last = step.last;
    const Vec2 g = sim.solid_body_acceleration(t + elapsed + step.size);
    solid_substep_velocity_verlet(solid, step.size, g);
    elapsed += step.size;
    ++count;
  }
}

void evaluate_forces(Simulation& sim, const Vec2& g) {
  FluidBody& fluid = sim.fluid();
  compute_pressure_interaction(fluid, sim.fluid_inner(), sim.fluid_contacts(), g);
  for (std::size_t s = 0; s < sim.solids().size(); ++s) set_force_from_fluid(sim.solid_contact(s), sim.solids()[s].particles);
}

}  // namespace

Real VelocityVerletSchedule::advance(Simulation& sim, Real max_step) {
  if (!sim.has_fluid()) throw std::invalid_argument("multi_step_velocity_verlet needs a fluid body");
  FluidBody& fluid = sim.fluid();
  std::vector<FluidContact>& contacts = sim.fluid_contacts();
  const NeighborList& inner = sim.fluid_inner();
  const Real t0 = sim.time;
  const Real Dt = std::min(advection_time_step(fluid, sim.fluid_body_acceleration(t0)), max_step);

  reinitialise_density(fluid, inner, contacts, density_relaxation_per_step(fluid.options));
  sim.impose_boundary_states(0.0);
  compute_viscous_force_and_transport_shift(fluid, inner, contacts, sim.fluid_body_acceleration(t0));
  for (SolidBody& solid : sim.solids()) update_solid_normals(solid);
  // The pair lists were rebuilt: forces of the current state on the new lists.
  advance_density_and_position(fluid, 0.0, 0.0);
  evaluate_forces(sim, sim.fluid_body_acceleration(t0));

  Real elapsed = 0.0;
  for (bool last = false; !last;) {
    const SplitStep step = split_remaining(Dt - elapsed, acoustic_time_step(fluid));
    const Real dt = step.size;
    last = step.last;
    kick(fluid, 0.5 * dt, sim.fluid_body_acceleration(sim.time));
    add_boundary_impulses(contacts, 0.5 * dt);
    advance_position(fluid, dt);
    add_velocity_divergence_and_dissipation(fluid, inner, contacts);
    advance_density_and_position(fluid, dt, 0.0);
    for (SolidBody& solid : sim.solids()) {
      begin_kinematics_average(solid.particles);
      integrate_solid_velocity_verlet(solid, sim, sim.time, dt, sim.steps.solid);
      end_kinematics_average(solid.particles, dt, sim.solid_kinematics);
    }
    elapsed += dt;
    sim.time = last ? t0 + Dt : t0 + elapsed;
    evaluate_forces(sim, sim.fluid_body_acceleration(sim.time));
    kick(fluid, 0.5 * dt, sim.fluid_body_acceleration(sim.time));
    add_boundary_impulses(contacts, 0.5 * dt);
    sim.impose_boundary_states(dt);
    ++sim.steps.acoustic;
  }
  sim.exchange_open_boundary_particles();
  sim.check_divergence();
  sim.rebuild_fluid_relations();
  ++sim.steps.advection;
  return Dt;
}

}  // namespace mrsph
