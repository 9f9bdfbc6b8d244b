// The state of one simulation: bodies, their relations, the clock and the step counters. No
// global state: two Simulations can run side by side in one process (the harness does).
// Schedules (time/) advance it; observers (observers/) read it.
#pragma once

#include "boundary/body_force.hpp"
#include "boundary/inflow.hpp"
#include "boundary/open_boundary.hpp"
#include "boundary/wall_body.hpp"
#include "core/errors.hpp"
#include "fluid/fluid_body.hpp"
#include "fsi/fluid_solid_coupling.hpp"
#include "neighbor/cell_grid.hpp"
#include "neighbor/domain_box.hpp"
#include "solid/solid_body.hpp"
#include "solid/solid_contact.hpp"

#include <optional>
#include <string>
#include <vector>

namespace mrsph {

struct StepCounters {
  long long advection = 0;
  long long acoustic = 0;
  long long solid = 0;  // solid sub-steps, summed over solid bodies
};

struct DivergenceLimits {
  Real speed_factor = 3.0;  // |v| above this multiple of the body's sound speed is a runaway
};

class Simulation {
 public:
  explicit Simulation(DomainBox box) : box_(box) {}
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Set-up: add bodies, then call initialise() once. Bodies cannot be added afterwards (the
  // relations keep pointers into them).
  void set_fluid(FluidBody fluid);
  WallBody& add_wall(WallBody wall);
  SolidBody& add_solid(SolidBody solid);
  void initialise();

  const DomainBox& box() const { return box_; }
  bool has_fluid() const { return fluid_.has_value(); }
  FluidBody& fluid() { return *fluid_; }
  const FluidBody& fluid() const { return *fluid_; }
  std::vector<WallBody>& walls() { return walls_; }
  const std::vector<WallBody>& walls() const { return walls_; }
  std::vector<SolidBody>& solids() { return solids_; }
  const std::vector<SolidBody>& solids() const { return solids_; }
  // The index in solids() of the solid body with this name, if there is one.
  std::optional<std::size_t> solid_index(const std::string& name) const;

  const NeighborList& fluid_inner() const { return fluid_inner_; }
  std::vector<FluidContact>& fluid_contacts() { return contacts_; }
  const std::vector<FluidContact>& fluid_contacts() const { return contacts_; }
  // The contact of the fluid with wall w / solid s.
  FluidContact& wall_contact(std::size_t w) { return contacts_[w]; }
  FluidContact& solid_contact(std::size_t s) { return contacts_[walls_.size() + s]; }
  const FluidContact& wall_contact(std::size_t w) const { return contacts_[w]; }
  const FluidContact& solid_contact(std::size_t s) const { return contacts_[walls_.size() + s]; }

  BodyForce body_force;
  bool body_force_on_solids = true;
  // The body acceleration of the fluid at time t: the body force and, in a channel periodic along
  // x, the inflow's channel drive (boundary/inflow.hpp). The solids': the body force, if on_solids.
  Vec2 fluid_body_acceleration(Real t) const;
  Vec2 solid_body_acceleration(Real t) const { return body_force_on_solids ? body_force.at(t) : Vec2::Zero(); }
  std::optional<InflowBuffer> inflow;
  std::vector<OpenBoundary> open_boundaries;
  SolidKinematics solid_kinematics = SolidKinematics::Averaged;
  // Contacts between solid bodies (set before initialise()); with any, all solids sub-step together.
  std::vector<SolidContact> solid_contacts;
  DivergenceLimits limits;

  Real time = 0.0;
  StepCounters steps;

  // Wraps fluid positions into the periodic box, rebuilds the fluid's cell lists and every fluid
  // pair list (cell lists of all bodies first, then the pairs, so both sides see the same
  // positions; METHOD.md section 6 step 8).
  void rebuild_fluid_relations();
  // After the particle state was restored from a checkpoint: rebuilds every pair list from the
  // restored positions exactly as the interrupted run had them (no wrap, no reordering).
  void restore_relations(std::size_t rebuild_count);
  std::size_t rebuild_count() const { return rebuilds_since_sort_; }
  // The buffer states of the open boundaries at the current time (after a density
  // re-initialisation: dt = 0), and after an acoustic step of size dt also the periodic inflow.
  void impose_boundary_states(Real dt);
  // Open boundaries: particles into and out of the buffers, created and deleted (open_boundary.hpp).
  // Once per advection step, before the relations are rebuilt.
  void exchange_open_boundary_particles();
  // Throws DivergenceError on NaN/Inf, runaway speed, a particle out of the domain or J <= 0.
  void check_divergence() const;

  std::size_t particle_count() const;

 private:
  std::optional<std::string> fluid_particle_fault(std::size_t i) const;

  DomainBox box_;
  std::optional<FluidBody> fluid_;
  std::vector<WallBody> walls_;
  std::vector<SolidBody> solids_;
  bool initialised_ = false;

  NeighborList fluid_inner_;
  std::vector<FluidContact> contacts_;
  std::size_t rebuilds_since_sort_ = 0;  // rebuilds so far; every kSortInterval-th one reorders
  std::vector<CellGrid> wall_grids_;      // the fixed walls' cell lists for the fluid's contacts, built once
  void build_pair_lists();
  // The fluid's and the solids' positions at the build, for refresh_pair_geometry and refresh_divergence_geometry.
  void record_positions_at_list_build();
  // Fluid options left to the scene (DensityReinitialisation and PressureReference Automatic):
  // a free surface where gravity acts along an axis that is not periodic, else a confined fluid.
  void resolve_automatic_fluid_options();
  // PressureReference::Linear: the contacts of the bodies immersed in the fluid read its gradient.
  void share_linear_reference_with_immersed_bodies();
  // Initial particle relaxation (FluidOptions::relaxation_steps), bodies held still, after the
  // perturbation of FluidOptions::relaxation_perturbation.
  void relax_fluid_particles();
};

}  // namespace mrsph
