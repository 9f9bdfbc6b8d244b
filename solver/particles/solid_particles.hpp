// Struct-of-arrays state of an elastic solid body in the total Lagrangian formulation. All
// interaction sums use the reference configuration (pos0, vol0).
#pragma once

#include "core/types.hpp"

#include <cstdint>
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
  Vec2Array normal;      // current normal, R(F) normal0
  Vec2Array force_prior; // force from the fluid, held constant over the solid sub-steps
  Vec2Array vel_ave;     // velocity averaged over the last acoustic step, seen by the fluid (Eq. 35)
  Vec2Array acc_ave;     // acceleration averaged likewise
  Vec2Array pos_acoustic_start;  // position at the start of the current acoustic step
  Vec2Array vel_acoustic_start;  // velocity at the start of the current acoustic step
  std::vector<std::uint8_t> constrained;  // 1: clamped (held at pos0 with zero velocity)

  std::size_t size() const { return pos.size(); }
  void resize(std::size_t n) {
    for (Vec2Array* a : {&pos0, &pos, &vel, &acc, &normal0, &normal, &force_prior, &vel_ave, &acc_ave, &pos_acoustic_start, &vel_acoustic_start})
      a->resize(n, Vec2::Zero());
    for (Mat2Array* a : {&F, &dF_dt, &B, &stress}) a->resize(n, Mat2::Zero());
    for (RealArray* a : {&rho, &mass, &vol0}) a->resize(n, 0.0);
    constrained.resize(n, 0);
  }
};

}  // namespace mrsph
