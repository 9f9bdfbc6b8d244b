// Contact between two elastic bodies: a penalty on the overlap of their particles. Not in the paper
// (its examples do not describe one); here two valve leaflets that close on each other would otherwise
// pass through one another, since solids interact only through the fluid (reports/valve.md). Of the
// kind the paper's code uses for solid contact (a "contact density" summed over the other body, and a
// pressure from it); the kernel, the force and the stiffness below are this project's choices.
//   kernel      W_c: Wendland C2 with support one solid spacing (h_c = dp / 2), so the force starts when
//               two particles' cells touch (centres dp apart) and the bodies keep no visible gap
//   overlap     phi_a = sum_{b in the other body} V_b W_c(r_ab)            (dimensionless, 0 when apart)
//   pressure    p_a = k_c phi_a
//   force       f_a = - sum_b V_a V_b (p_a + p_b) dW_c/dr(r_ab) e_ab,  e_ab = (r_a - r_b) / r_ab
// f_a is antisymmetric in the pair, so momentum is conserved exactly; it pushes along the line of
// centres only, so angular momentum too. Volumes are the reference volumes V0.
// Stiffness: k_c = rho0 c_S^2 by default (c_S the solid's sound speed; the smaller rho0 c_S^2 of the two
// bodies). Why that scale: to stop a body arriving at speed v the contact pressure must reach its
// acoustic impedance times v, rho0 c_S v, so the overlap grows as phi ~ v / c_S: small at the speeds of
// interest (two blocks meeting at Mach 0.1 keep their closest particles 0.63 dp apart, at Mach 0.017
// 0.76 dp; with k_c 1/500 of it they went through each other). Stability: the force is that of the
// potential sum_a V_a k_c phi_a^2 / 2, whose stiffness grows as the overlap deepens (at 0.63 dp a pair
// alone has omega dt = 2.9 at the paper's solid step); each particle's share of it (add_contact_forces)
// enters the solid's time-step criterion (solid/step_criterion.hpp), so the sub-step shortens in contact.
// A fixed wall as the second body: the same penalty with the wall's dummy particles as b, whose
// reaction is not applied (the wall is fixed). The solid's clamped particles take no part: the clamp
// is their attachment to the wall, where they sit inside the contact's reach for ever. Without it a
// valve leaflet pushed upstream by a reversed pressure passed through the vein wall
// (reports/open-boundaries.md).
#pragma once

#include "kernel/wendland_c2.hpp"
#include "particles/wall_particles.hpp"
#include "solid/solid_body.hpp"

#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace mrsph {

struct SolidContact {
  std::size_t first = 0, second = 0;  // indices of the two bodies in the simulation's solids
  bool second_is_wall = false;        // then `second` indexes the simulation's walls
  Real stiffness = 0.0;               // k_c [Pa]; 0 means the default above

  // Derived by prepare_solid_contact; the candidate pairs are a Verlet list of radius support + skin,
  // rebuilt when the bodies may have moved by more than the skin since (travel > skin).
  WendlandC2 kernel{1.0};
  Real skin = 0.0;
  Real travel = std::numeric_limits<Real>::infinity();
  std::vector<std::pair<Index, Index>> candidates;  // (a in first, b in second), sorted
  // A wall's particles (positions, volumes), copied by prepare_wall_contact: a wall never moves.
  Vec2Array wall_pos;
  RealArray wall_vol;
};

Real default_contact_stiffness(const SolidBody& a, const SolidBody& b);

// Sets the kernel (support = the larger dp), the skin (half a support) and the default stiffness.
void prepare_solid_contact(SolidContact& contact, const SolidBody& a, const SolidBody& b);

// Rebuilds the candidate pairs if the bodies may have moved by more than the skin since the last
// build (contact.travel, advanced by the caller).
void refresh_contact_candidates(SolidContact& contact, const SolidBody& a, const SolidBody& b);

// Adds the contact forces of the current positions to both bodies' external_force.
void add_contact_forces(const SolidContact& contact, SolidBody& a, SolidBody& b);

// The largest overlap phi over both bodies (0 when apart), for diagnostics and tests.
Real largest_contact_overlap(const SolidContact& contact, const SolidBody& a, const SolidBody& b);

// The same for a solid and a fixed wall (contact.second_is_wall): the kernel's support is the larger
// spacing, the default stiffness the solid's rho0 c_S^2; forces go to the solid only.
void prepare_wall_contact(SolidContact& contact, const SolidBody& solid, const WallParticles& wall, Real wall_dp);
void refresh_contact_candidates(SolidContact& contact, const SolidBody& solid);
void add_contact_forces(const SolidContact& contact, SolidBody& solid);
Real largest_contact_overlap(const SolidContact& contact, const SolidBody& solid);

// Refreshes the candidates of any contact and adds its forces: the solids' external_force.
void apply_contact(SolidContact& contact, std::span<SolidBody> solids);

}  // namespace mrsph
