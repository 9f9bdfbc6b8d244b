// Observers: what a run records over time.
//   solid body, "position" / "displacement": a kernel-weighted average over a fixed set of material
//     particles chosen at t = 0 around the point (weights W V, normalised; METHOD.md section 8),
//     or the single nearest particle. Displacement = position - reference position, so a probe
//     that sits inside the tip does not bias the mean.
//   fluid body, "velocity" / "pressure": a Shepard average of the fluid particles within the
//     fluid's kernel support of the point, at the sampling time.
//   boundary bodies, "force": the total force of the fluid on the listed wall and solid bodies
//     (fx, fy) and its viscous part (fx_viscous, fy_viscous), averaged over the time since the
//     previous record (the observer interval, or the advection step when observers record every
//     step); the rest is the pressure's (and the Riemann dissipation's, if on).
//   fluid body, "front": the largest coordinate of the fluid particles along a direction (the
//     surge front of a dam break), max_i r_i . d.
//   two solid bodies, "gap": the smallest distance between a particle of one and a particle of the
//     other (bodies in contact keep it near one solid spacing; less than half of one means they are
//     passing into each other). All pairs are compared: meant for small bodies such as leaflets.
#pragma once

#include "simulation/simulation.hpp"

#include <string>
#include <vector>

namespace mrsph {

enum class ObservedQuantity { Position, Displacement, Velocity, Pressure, Force, Front, Gap };

struct ObserverSpec {
  std::string name;
  std::vector<std::string> bodies;  // one body, several for "force", two for "gap"
  Vec2 point = Vec2::Zero();
  Vec2 direction = Vec2(1.0, 0.0);  // for "front"
  ObservedQuantity quantity = ObservedQuantity::Position;
  bool nearest_particle = false;
};

class PointObserver {
 public:
  // Throws std::invalid_argument if a body is unknown or the quantity does not fit the body.
  PointObserver(ObserverSpec spec, const Simulation& sim);

  const std::string& name() const { return spec_.name; }
  const ObserverSpec& spec() const { return spec_; }
  std::vector<std::string> columns() const;
  std::vector<Real> sample(const Simulation& sim) const;
  // The fluid contacts (Simulation::fluid_contacts) whose force this observer reads: they must keep
  // their impulse record (FluidContact::records_impulse).
  const std::vector<std::size_t>& force_contacts() const { return contact_indices_; }

 private:
  enum class Target { Fluid, Solid, Boundaries, SolidPair };
  // The constructor's cases, by what is observed.
  void observe_forces(const Simulation& sim);
  void observe_gap(const Simulation& sim);
  void observe_fluid();
  void observe_solid(const SolidBody& solid);
  ObserverSpec spec_;
  Target target_ = Target::Fluid;
  std::size_t solid_index_ = 0;
  std::size_t other_solid_index_ = 0;  // gap: the second body
  std::vector<std::size_t> contact_indices_;
  std::vector<Index> particles_;  // solid: fixed material particles
  std::vector<Real> weights_;
};

}  // namespace mrsph
