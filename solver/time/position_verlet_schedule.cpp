#include "time/position_verlet_schedule.hpp"

#include "fluid/acoustic_step.hpp"
#include "fluid/advection_pair_terms.hpp"
#include "fluid/density_summation.hpp"
#include "fluid/fluid_time_step.hpp"
#include "fsi/fluid_solid_coupling.hpp"
#include "solid/solid_dynamics.hpp"
#include "core/parallel.hpp"
#include "core/step_splitting.hpp"

#include <algorithm>
#include <limits>

namespace mrsph {

long long integrate_solid_over(SolidBody& solid, const Simulation& sim, Real t, Real dt) {
  return advance_solid(solid, t, dt, [&](Real time) {
    return sim.solid_body_acceleration(time);
  });
}

long long integrate_solids_over(Simulation& sim, Real t, Real dt) {
  if (sim.solid_contacts.empty()) {
    long long count = 0;
    for (SolidBody& solid : sim.solids()) count += integrate_solid_over(solid, sim, t, dt);
    return count;
  }
  return advance_solids(sim.solids(), sim.solid_contacts, t, dt, [&](Real time) {
    return sim.solid_body_acceleration(time);
  });
}

Real PositionVerletSchedule::advance_solids_only(Simulation& sim, Real max_step) {
  // Without a fluid an "advection step" is a batch of solid steps; 200 keeps progress and the
  // divergence checks frequent.
  Real criterion = std::numeric_limits<Real>::infinity();
  for (const SolidBody& solid : sim.solids()) criterion = std::min(criterion, solid_time_step(solid));
  const Real Dt = std::min(max_step, 200.0 * criterion);
  sim.steps.solid += integrate_solids_over(sim, sim.time, Dt);
  sim.time += Dt;
  ++sim.steps.acoustic;
  sim.check_divergence();
  ++sim.steps.advection;
  return Dt;
}

Real PositionVerletSchedule::advance(Simulation& sim, Real max_step) {
  if (!sim.has_fluid()) return advance_solids_only(sim, max_step);
  FluidBody& fluid = sim.fluid();
  std::vector<FluidContact>& contacts = sim.fluid_contacts();
  const NeighborList& inner = sim.fluid_inner();
  const Real t0 = sim.time;
  const Real Dt = std::min(advection_time_step(fluid, sim.fluid_body_acceleration(t0)), max_step);

  // Algorithm 1, once per advection step.
  reinitialise_density(fluid, inner, contacts, density_relaxation_per_step(fluid.options));
  sim.impose_boundary_states(0.0);
  compute_viscous_force_and_transport_shift(fluid, inner, contacts, sim.fluid_body_acceleration(t0));
  for (SolidBody& solid : sim.solids()) update_solid_normals(solid);

  Real elapsed = 0.0, step_length = Dt;
  for (bool last = false; !last;) {
    Real criterion = acoustic_time_step(fluid);
    if (single_step_)
      for (const SolidBody& solid : sim.solids()) criterion = std::min(criterion, solid_time_step(solid));
    const SplitStep step = acoustic_steps_ == AcousticSteps::FullSteps ? full_step_towards(elapsed, Dt, max_step, criterion)
                           : acoustic_steps_ == AcousticSteps::FullStepsInside
                               ? full_step_inside(elapsed, Dt, max_step, criterion)
                               : split_remaining(Dt - elapsed, criterion);
    const Real dt = step.size;
    last = step.last;

    acoustic_first_half(fluid, inner, contacts, dt, sim.fluid_body_acceleration(sim.time + 0.5 * dt));
    add_boundary_impulses(contacts, dt);
    for (std::size_t s = 0; s < sim.solids().size(); ++s)
      set_force_from_fluid(sim.solid_contact(s), sim.solids()[s].particles);
    for (SolidBody& solid : sim.solids()) begin_kinematics_average(solid.particles);
    // The solids' sub-steps read of the fluid only the forces just set; the fluid's second half reads
    // of the solids only their volumes, normals and the previous step's averaged kinematics. So the
    // two run side by side; the solids' loops take the other thread when it is free (LoopTeam).
    // A fluid alone keeps its static blocks and spawns nothing.
    if (sim.solids().empty())
      acoustic_second_half(fluid, inner, contacts, dt);
    else
      run_side_by_side([&] { acoustic_second_half(fluid, inner, contacts, dt, Sharing::Balanced); },
                       [&] { sim.steps.solid += integrate_solids_over(sim, sim.time, dt); });
    for (SolidBody& solid : sim.solids()) end_kinematics_average(solid.particles, dt, sim.solid_kinematics);
    // The equal split ends on Dt exactly; full steps where they end, or on max_step exactly.
    const bool full_steps = acoustic_steps_ != AcousticSteps::EqualSplit;
    const bool on_limit = full_steps && dt == max_step - elapsed;
    elapsed += dt;
    if (last) step_length = full_steps ? (on_limit ? max_step : elapsed) : Dt;
    sim.time = last ? t0 + step_length : t0 + elapsed;
    sim.impose_boundary_states(dt);
    ++sim.steps.acoustic;
  }
  sim.exchange_open_boundary_particles();
  sim.check_divergence();
  sim.rebuild_fluid_relations();
  ++sim.steps.advection;
  return step_length;
}

}  // namespace mrsph
