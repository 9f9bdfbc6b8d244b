#include "solid/gradient_weights.hpp"

#include "core/parallel.hpp"
#include "interaction/pair_sweep.hpp"
#include "solid/constitutive/elastic_moduli.hpp"

#include <Eigen/Dense>

#include <stdexcept>

namespace mrsph {

GradientCorrection gradient_correction_from_name(const std::string& name) {
  if (name == "first_order") return GradientCorrection::FirstOrder;
  if (name == "second_order") return GradientCorrection::SecondOrder;
  if (name == "second_order_with_corners") return GradientCorrection::SecondOrderWithCorners;
  throw std::invalid_argument("unknown gradient correction '" + name +
                              "', expected \"first_order\", \"second_order\" or \"second_order_with_corners\"");
}

namespace {

using Vec5 = Eigen::Matrix<Real, 5, 1>;
using Mat5 = Eigen::Matrix<Real, 5, 5>;

// (M^T M + eps I)^-1 M^T, as the paper's code inverts B.
Mat2 regularised_inverse(const Mat2& M) { return (M.transpose() * M + 1e-8 * Mat2::Identity()).inverse() * M.transpose(); }

// The pair's kernel factor phi_ab = V0_b (-dW/dr) / r.
Real pair_factor(const RealArray& vol0, const Neighbor& nb) { return vol0[nb.j] * (-nb.dW) / nb.r; }

// The quadratic basis of d = r0_b - r0_a scaled by h (so that the moment matrix is well-conditioned).
Vec5 quadratic_basis(const Neighbor& nb, Real h) {
  const Vec2 d = -nb.r * nb.e / h;
  Vec5 p;
  p << d.x(), d.y(), 0.5 * d.x() * d.x(), d.x() * d.y(), 0.5 * d.y() * d.y();
  return p;
}

// Linear (the paper's B0): M = sum_b phi_ab d d^T, d = r0_b - r0_a = -r e; w_ab = phi_ab B d.
void linear_weights(const NeighborList& reference, std::size_t a, const RealArray& vol0, Mat2& B, Vec2Array& w) {
  Mat2 M = Mat2::Zero();
  for_each_pair(reference, a, [&](Index, const Neighbor& nb) {
    const Vec2 d = -nb.r * nb.e;
    M += pair_factor(vol0, nb) * d * d.transpose();
  });
  B = regularised_inverse(M);
  for_each_pair(reference, a, [&](Index k, const Neighbor& nb) { w[k] = pair_factor(vol0, nb) * (B * (-nb.r * nb.e)); });
}

// A corner or tip of the outline: the support's normalised first moment |sum_b phi_ab d| / sum_b
// phi_ab |d| above kCornerMoment. For a continuous support cut to a wedge of angle alpha it is
// 2 sin(alpha/2) / alpha: 0 inside, 2/pi = 0.64 at a straight surface, 0.90 at a right-angled corner.
// On a lattice the particle's own row lowers it: at h = 1.15-1.3 dp a straight surface gives 0.42-0.45,
// a lattice step on a curved outline 0.56-0.66, a right-angled corner 0.76-0.77.
constexpr Real kCornerMoment = 0.7;
bool at_corner(const NeighborList& reference, std::size_t a, const RealArray& vol0) {
  Vec2 moment = Vec2::Zero();
  Real scale = 0.0;
  for_each_pair(reference, a, [&](Index, const Neighbor& nb) {
    const Real phi = pair_factor(vol0, nb);
    moment -= phi * nb.r * Vec2(nb.e);
    scale += phi * nb.r;
  });
  return scale > 0.0 && moment.norm() > kCornerMoment * scale;
}

// Exact for quadratic fields: the first two rows of the 5 x 5 moment matrix's inverse. False (weights
// untouched) where the neighbours do not determine a quadratic.
bool quadratic_weights(const NeighborList& reference, std::size_t a, const RealArray& vol0, Real h, Vec2Array& w) {
  Mat5 M5 = Mat5::Zero();
  for_each_pair(reference, a, [&](Index, const Neighbor& nb) {
    const Vec5 p = quadratic_basis(nb, h);
    M5 += pair_factor(vol0, nb) * p * p.transpose();
  });
  const Eigen::FullPivLU<Mat5> lu(M5);
  if (!lu.isInvertible() || lu.rcond() < 1e-6) return false;
  const Mat5 inverse = lu.inverse();
  for_each_pair(reference, a, [&](Index k, const Neighbor& nb) {
    const Vec5 c = inverse * quadratic_basis(nb, h);
    w[k] = (pair_factor(vol0, nb) / h) * Vec2(c(0), c(1));
  });
  return true;
}

// Reverse weights: entry (a, b) gets w_ba from b's list (the reference list is symmetric); and w_sum.
void reverse_weights(const NeighborList& reference, GradientWeights& g) {
  parallel_for_each(reference.size(), [&](std::size_t a) {
    Vec2 sum = Vec2::Zero();
    for_each_pair(reference, a, [&](Index k, const Neighbor& nb) {
      sum += g.w[k];
      const long back = pair_index(reference, nb.j, static_cast<Index>(a));
      if (back >= 0) g.w_reverse[k] = g.w[back];
    });
    g.w_sum[a] = sum;
  });
}

}  // namespace

GradientWeights compute_gradient_weights(const NeighborList& reference, const RealArray& vol0, Real h,
                                         GradientCorrection correction) {
  const std::size_t n = reference.size();
  GradientWeights g;
  g.neighbor = pair_neighbors(reference);
  g.w.assign(reference.pair_count(), Vec2::Zero());
  g.w_reverse.assign(reference.pair_count(), Vec2::Zero());
  g.w_sum.assign(n, Vec2::Zero());
  g.B.assign(n, Mat2::Identity());
  std::vector<std::uint8_t> second(n, 0);
  parallel_for_each(n, [&](std::size_t a) {
    linear_weights(reference, a, vol0, g.B[a], g.w);
    const bool quadratic = correction == GradientCorrection::SecondOrderWithCorners ||
                           (correction == GradientCorrection::SecondOrder && !at_corner(reference, a, vol0));
    if (quadratic) second[a] = quadratic_weights(reference, a, vol0, h, g.w) ? 1 : 0;
  });
  reverse_weights(reference, g);
  for (auto s : second) g.second_order_count += s;
  return g;
}

void calibrate_time_step(GradientWeights& g, const NeighborList& reference, const RealArray& vol0, const RealArray& mass,
                         const std::vector<std::uint8_t>& constrained, Real h, Real lambda, Real shear_modulus) {
  const GradientWeights paper = compute_gradient_weights(reference, vol0, h, GradientCorrection::FirstOrder);
  const Real omega2_paper = highest_frequency_squared(reference, paper.w, paper.w_reverse, paper.w_sum, vol0, mass,
                                                      constrained, lambda, shear_modulus);
  const Real omega2_used =
      highest_frequency_squared(reference, g.w, g.w_reverse, g.w_sum, vol0, mass, constrained, lambda, shear_modulus);
  if (omega2_used > omega2_paper && omega2_paper > 0.0) g.time_step_scale = std::sqrt(omega2_paper / omega2_used);
  g.highest_frequency = std::sqrt(omega2_used);
}

Real highest_frequency_squared(const NeighborList& reference, const Vec2Array& w, const Vec2Array& w_reverse,
                               const Vec2Array& w_sum, const RealArray& vol0, const RealArray& mass,
                               const std::vector<std::uint8_t>& constrained, Real lambda, Real shear_modulus) {
  const std::size_t n = reference.size();
  Vec2Array u(n), f(n);
  Mat2Array stress(n);
  const std::vector<Index> neighbor = pair_neighbors(reference);
  // A deterministic, non-smooth start excites every mode.
  for (std::size_t a = 0; a < n; ++a)
    u[a] = constrained[a] ? Vec2::Zero() : Vec2(std::sin(12.9898 * a + 1.0), std::cos(78.233 * a + 2.0));
  Real estimate = 0.0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    parallel_for_each(n, [&](std::size_t a) {
      const Mat2 grad = weighted_gradient(reference, neighbor, w, u, a);
      stress[a] = linear_elastic_stress({lambda, shear_modulus}, 0.5 * (grad + grad.transpose()));
    });
    parallel_for_each(n, [&](std::size_t a) {
      if (constrained[a]) { f[a].setZero(); return; }
      f[a] = variational_force(reference, neighbor, w_reverse, w_sum[a], vol0, stress, a) / mass[a];
    });
    Real norm_u = 0.0, norm_f = 0.0;
    for (std::size_t a = 0; a < n; ++a) { norm_u += u[a].squaredNorm(); norm_f += f[a].squaredNorm(); }
    if (norm_f == 0.0 || norm_u == 0.0) return 0.0;
    estimate = std::sqrt(norm_f / norm_u);
    const Real scale = 1.0 / std::sqrt(norm_f);
    for (std::size_t a = 0; a < n; ++a) u[a] = f[a] * scale;
  }
  return estimate;
}

}  // namespace mrsph
