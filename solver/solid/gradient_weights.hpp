// Gradient weights of the total Lagrangian solid: F_a = I + sum_b (u_b - u_a) (x) w_ab, computed once
// in the reference configuration.
//
// The paper's kernel correction (Eq. 16), w_ab = V_b B_a grad0_a W_ab with B_a = (sum_b V_b (r0_b -
// r0_a) (x) grad0_a W_ab)^-1, is the weighted least-squares gradient with weight
// phi_ab = V_b |W'_ab| / r_ab and a linear basis: exact for linear displacement fields. At a free
// surface the one-sided stencil then gets the gradient of a quadratic field (bending) wrong by
// O(h): the surface strain, and the bending stiffness, come out low (the cantilever plate at 4
// particles through the thickness oscillates 30 % slow).
//
// Second order: the same weight with the basis (dx, dy, dx^2/2, dx dy, dy^2/2), so the gradient is
// exact for quadratic fields everywhere. On a uniform lattice the odd moments vanish away from
// surfaces and the weights there equal the paper's. Where the quadratic fit is ill-conditioned (a
// particle with too few neighbours) the linear weights are used.
//
// Corners keep the paper's weights. Where the support is cut on two sides (a convex corner or tip
// of the outline), two traction-free faces with independent normals make the stress vanish (P N1 =
// P N2 = 0), so the gradient's accuracy there carries no stiffness; the quadratic fit over a quarter
// of a support only adds weights: it raised the highest eigenfrequency of the gate, the plate and
// FSI2's beam 1.23-1.31 times, and with it the solid's step count (reports/performance.md section 12).
// Bodies in contact keep the quadratic fits at corners (solid_dynamics.cpp, correction_in_use).
//
// The internal force is the variational one for any such weights,
//   f_a = -dE/dr_a = V_a P_a sum_b w_ab - sum_b V_b P_b w_ba,  E = sum_c V_c Psi(F_c),
// which conserves linear and angular momentum and energy; for the paper's weights it is exactly
// the paper's Eq. 29.
#pragma once

#include "core/types.hpp"
#include "interaction/pair_sweep.hpp"
#include "neighbor/neighbor_list.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace mrsph {

// FirstOrder: the paper's B0 everywhere. SecondOrder: quadratic fits except at corners (the default).
// SecondOrderWithCorners: quadratic fits at corners too (this project's earlier default; for comparison).
enum class GradientCorrection { FirstOrder, SecondOrder, SecondOrderWithCorners };

GradientCorrection gradient_correction_from_name(const std::string& name);  // throws std::invalid_argument

struct GradientWeights {
  std::vector<Index> neighbor;  // per pair entry k = (a, b) of the reference list: b (compact copy)
  Vec2Array w;          // per pair entry k = (a, b) of the reference list: w_ab
  Vec2Array w_reverse;  // per pair entry k = (a, b): w_ba
  Vec2Array w_sum;      // per particle: sum_b w_ab
  Mat2Array B;          // per particle: the paper's B0 (reported; the first-order fallback)
  std::size_t second_order_count = 0;  // particles with second-order weights
  // omega_max(B0) / omega_max(used): the ratio of the highest eigenfrequencies of the linearised
  // discrete elasticity operator with the paper's weights and with the weights in use. The paper's
  // step criterion (Eq. 34, factor 0.6) is calibrated for B0; multiplied by this ratio it keeps the
  // same stability margin for other weights (1 for the paper's weights). Set by initialise_solid.
  Real time_step_scale = 1.0;
  // omega_max of the weights in use (0 where not computed: the paper's weights). Reported by
  // `mrsph check` with omega_max dt_S: position Verlet is stable for omega_max dt_S < 2.
  Real highest_frequency = 0.0;
  // The Kelvin-Voigt damping's largest decay rate (1/s; 0 without damping): the linearised operator
  // v -> f(v)/m of the viscous stress eta sym(grad v), plane-strain elasticity with Lame constants 0
  // and eta / 2 acting on velocities. Set by initialise_solid; the step keeps rate dt below
  // kDampingStepLimit (step_criterion.hpp).
  Real highest_damping_rate = 0.0;
};

// sum_b (u_b - u_a) (x) w_ab over a's pairs (neighbor: the pairs' b, GradientWeights::neighbor): the
// gradient of a field u, dF/dt for the velocity (Eq. 17), F - I for the displacement.
inline Mat2 weighted_gradient(const NeighborList& reference, const std::vector<Index>& neighbor, const Vec2Array& w,
                              const Vec2Array& u, std::size_t a) {
  // Column by column: the same products and sums as gradient += du w^T, but with AVX GCC turns that
  // 2x2 update into two 16-byte stores read back as one 32-byte load, which stalls (the `native`
  // build ran the gate at half speed; reports/performance.md section 10).
  Vec2 column0 = Vec2::Zero(), column1 = Vec2::Zero();
  for_each_pair_index(reference, a, [&](Index k) {
    const Vec2 du = u[neighbor[k]] - u[a];
    column0 += du * w[k].x();
    column1 += du * w[k].y();
  });
  Mat2 gradient;
  gradient << column0, column1;
  return gradient;
}

// The variational internal force f_a = V_a P_a sum_b w_ab - sum_b V_b P_b w_ba (header).
inline Vec2 variational_force(const NeighborList& reference, const std::vector<Index>& neighbor,
                              const Vec2Array& w_reverse, const Vec2& w_sum_a, const RealArray& vol0,
                              const Mat2Array& stress, std::size_t a) {
  Vec2 force = vol0[a] * (stress[a] * w_sum_a);
  for_each_pair_index(reference, a, [&](Index k) { force -= vol0[neighbor[k]] * (stress[neighbor[k]] * w_reverse[k]); });
  return force;
}

// Highest eigenfrequency squared of the linearised operator u -> f(u)/m (plane-strain linear
// elasticity with Lame constants lambda, G), by power iteration; constrained particles are fixed.
Real highest_frequency_squared(const NeighborList& reference, const Vec2Array& w, const Vec2Array& w_reverse,
                               const Vec2Array& w_sum, const RealArray& vol0, const RealArray& mass,
                               const std::vector<std::uint8_t>& constrained, Real lambda, Real shear_modulus);

GradientWeights compute_gradient_weights(const NeighborList& reference, const RealArray& vol0, Real h,
                                         GradientCorrection correction);

// Keeps the paper's stability margin for weights other than its own: sets g.time_step_scale to
// omega_max(B0) / omega_max(g) (at most 1) and g.highest_frequency to omega_max(g).
void calibrate_time_step(GradientWeights& g, const NeighborList& reference, const RealArray& vol0, const RealArray& mass,
                         const std::vector<std::uint8_t>& constrained, Real h, Real lambda, Real shear_modulus);

}  // namespace mrsph
