// An elastic solid body: particles, resolution, material, and its neighbour list in the
// reference configuration (built once; total Lagrangian).
#pragma once

#include "kernel/wendland_c2.hpp"
#include "neighbor/neighbor_list.hpp"
#include "particles/boundary_view.hpp"
#include "particles/solid_particles.hpp"
#include "solid/elastic_material.hpp"
#include "solid/gradient_weights.hpp"

#include <optional>
#include <string>

namespace mrsph {

struct SolidOptions {
  Real cfl = 0.6;  // paper Eq. 34
  // Optional Kelvin-Voigt damping (off by default; not in the paper): a viscous second
  // Piola-Kirchhoff stress S_v = eta dE/dt with eta = coefficient * rho0 c_S h. Its damping ratio
  // grows with frequency, ~ eta omega / (2 E): it removes particle-scale noise (omega ~ c_S / h)
  // and barely touches structural modes. The 2020 version of the paper's code used 0.5.
  Real damping_coefficient = 0.0;
  // Gradient weights (gradient_weights.hpp): the paper's B0 (first order) or exact for quadratic
  // fields (second order, the default: bending of thin bodies).
  GradientCorrection gradient_correction = GradientCorrection::SecondOrder;
};

// A part of the body that moves as one rigid body: the fish's head in the paper's code. Each sub-step
// the accelerations of its particles (elastic forces from the rest of the body, the fluid, tethers)
// are replaced by the rigid-body motion they produce: a_i = a_c + alpha x d_i - omega^2 d_i, with
// d_i = r_i - r_c, a_c = sum m a / M, alpha = sum d x m a / I, omega = sum d x m v / I.
struct RigidRegion {
  std::vector<Index> particles;
};

// A cable from a fixed anchor to some particles (pulling at their mass centre r_c), taut only when
// stretched: x = |anchor - r_c| - L0; if x > 0 the tension is k x (1 + c dx/dt) along the cable
// (the paper's code's tether), shared among the particles by mass.
struct Tether {
  Vec2 anchor = Vec2::Zero();
  Real rest_length = 0.0;
  Real stiffness = 0.0;
  Real damping = 0.0;  // c, in units of time
  std::vector<Index> particles;
};

struct SolidBody {
  std::string name;
  Real dp;
  WendlandC2 kernel;
  ElasticMaterial material;
  SolidOptions options;
  SolidParticles particles;
  NeighborList inner;  // reference configuration
  GradientWeights weights;  // per pair of `inner`, built once
  // Particles the sub-steps must visit: the free ones and the clamped ones with a free neighbour.
  // A clamped particle whose neighbours are all clamped keeps F = I and P = 0 for ever.
  std::vector<Index> active;
  std::optional<RigidRegion> rigid;
  std::vector<Tether> tethers;
  Vec2Array external_force;  // tether and contact forces of the current sub-step, per particle
  bool in_contact = false;   // has a contact with another solid (solid_contact.hpp)

  SolidBody(std::string body_name, Real spacing, Real h_over_dp, ElasticMaterial elastic)
      : name(std::move(body_name)), dp(spacing), kernel(h_over_dp * spacing), material(std::move(elastic)) {}
  Real h() const { return kernel.h(); }
  BoundaryView boundary_view() const {
    return BoundaryView{&particles.vol0, &particles.normal, &particles.vel_ave, &particles.acc_ave, &particles.pos,
                        &particles.depth0};
  }
};

}  // namespace mrsph
