// Struct-of-arrays state of an elastic solid body in the total Lagrangian formulation. All
// interaction sums use the reference configuration (pos0, vol0).
#pragma once

#include "core/types.hpp"

#include <cstdint>
#include <type_traits>
#include <vector>

namespace mrsph {

struct SolidParticles {
  Vec2Array pos0;        // reference (initial) position
  Vec2Array pos;         // current position
  Vec2Array vel;         // velocity
  Vec2Array acc;         // acceleration of the last sub-step (for the time-step criterion)
  Mat2Array F;           // deformation gradient
  Mat2Array dF_dt;       // its rate, from the velocity field
  Mat2Array B;           // kernel correction matrix B0 (reference configuration; reported)
  Mat2Array stress;      // first Piola-Kirchhoff stress P (with the optional damping part)
  RealArray rho;         // density rho0 / J
  RealArray mass;
  RealArray vol0;        // reference volume, never updated
  Vec2Array normal0;     // outward normal in the reference configuration
  RealArray depth0;      // distance below the body's surface in the reference configuration (viscous wall rule)
  Vec2Array normal;      // current normal, R(F) normal0
  Vec2Array force_prior; // force from the fluid, held constant over the solid sub-steps
  Vec2Array vel_ave;     // velocity averaged over the last acoustic step, seen by the fluid (Eq. 35)
  Vec2Array acc_ave;     // acceleration averaged likewise
  Vec2Array pos_acoustic_start;  // position at the start of the current acoustic step
  Vec2Array vel_acoustic_start;  // velocity at the start of the current acoustic step
  RealArray contact_stiffness;   // contacts' stiffness at the particle, last sub-step [N/m] (solid_contact.cpp)
  std::vector<std::uint8_t> constrained;  // 1: clamped (held at pos0 with zero velocity)

  // The one list of fields: resize and the checkpoint go through it. Particles is SolidParticles or
  // const SolidParticles; visit(array, name) for each field. The state fields change in time (the
  // checkpoint keeps them); the reference fields are set once from the scene (rebuilt on restart).
  template <class Particles, class Visit>
  static void for_each_state_field(Particles& s, Visit&& visit) {
    visit(s.pos, "solid positions"); visit(s.vel, "solid velocities"); visit(s.acc, "solid accelerations");
    visit(s.F, "deformation gradients"); visit(s.dF_dt, "deformation rates"); visit(s.stress, "stresses");
    visit(s.rho, "solid densities"); visit(s.normal, "solid normals"); visit(s.force_prior, "forces from the fluid");
    visit(s.vel_ave, "averaged velocities"); visit(s.acc_ave, "averaged accelerations");
    visit(s.pos_acoustic_start, "acoustic-step start positions");
    visit(s.vel_acoustic_start, "acoustic-step start velocities");
    visit(s.contact_stiffness, "contact stiffnesses");
  }
  template <class Particles, class Visit>
  static void for_each_field(Particles& s, Visit&& visit) {
    visit(s.pos0, "reference positions"); visit(s.B, "correction matrices"); visit(s.mass, "solid masses");
    visit(s.vol0, "reference volumes"); visit(s.normal0, "reference normals"); visit(s.depth0, "reference depths");
    visit(s.constrained, "clamped flags");
    for_each_state_field(s, visit);
  }

  std::size_t size() const { return pos.size(); }
  // New entries are zero.
  void resize(std::size_t n) {
    for_each_field(*this, [n](auto& a, const char*) {
      using Value = typename std::decay_t<decltype(a)>::value_type;
      if constexpr (std::is_arithmetic_v<Value>) a.resize(n, Value(0));
      else a.resize(n, Value::Zero());
    });
  }
};

}  // namespace mrsph
