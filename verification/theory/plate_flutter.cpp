#include "theory/plate_flutter.hpp"

#include "theory/exponential_integral.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrsph::verification::theory {

namespace {

constexpr double two_pi = 2.0 * M_PI;

}  // namespace

VortexLattice::VortexLattice(double x_begin, double x_end, int panels, double stream_speed, double fluid_density)
    : U_(stream_speed), rho_(fluid_density), x_end_(x_end) {
  if (panels < 2 || !(x_end > x_begin) || !(stream_speed > 0.0))
    throw std::invalid_argument("vortex lattice: needs at least 2 panels, x_end > x_begin and a positive stream speed");
  std::vector<double> edge(panels + 1), width(panels);
  for (int k = 0; k <= panels; ++k) edge[k] = x_begin + (x_end - x_begin) * 0.5 * (1.0 - std::cos(M_PI * k / panels));
  for (int k = 0; k < panels; ++k) {
    width[k] = edge[k + 1] - edge[k];
    vortex_.push_back(edge[k] + 0.25 * width[k]);
    collocation_.push_back(edge[k] + 0.75 * width[k]);
    centre_.push_back(edge[k] + 0.5 * width[k]);
  }
  bound_.resize(panels, panels);
  unsteady_.setZero(panels, panels);
  for (int i = 0; i < panels; ++i) {
    for (int j = 0; j < panels; ++j) bound_(i, j) = 1.0 / (two_pi * (collocation_[i] - vortex_[j]));
    // The pressure jump's unsteady term needs the circulation bound upstream of each point; over
    // panel i that is the panels before it and half of its own.
    for (int j = 0; j < i; ++j) unsteady_(i, j) = -rho_ * width[i];
    unsteady_(i, i) = -0.5 * rho_ * width[i];
  }
}

Eigen::VectorXcd VortexLattice::wake_influence(Complex lambda) const {
  Eigen::VectorXcd wake = Eigen::VectorXcd::Zero(panels());
  if (std::abs(lambda) == 0.0) return wake;
  // Vorticity shed at the trailing edge, -(1/U) dGamma/dt, convected at U:
  // gamma_w(xi) = -(lambda / U) Gamma e^{-lambda (xi - x_end) / U}; its lateral velocity at a point a
  // distance d upstream of the trailing edge is (lambda Gamma / (2 pi U)) e^{a d} E1(a d), a = lambda / U.
  const Complex a_rate = lambda / U_;
  for (int i = 0; i < panels(); ++i) {
    const double d = x_end_ - collocation_[i];
    wake(i) = lambda / (two_pi * U_) * std::exp(a_rate * d) * exponential_integral_e1(a_rate * d);
  }
  return wake;
}

Eigen::MatrixXcd VortexLattice::influence(Complex lambda) const {
  Eigen::MatrixXcd a = bound_.cast<Complex>();
  a.colwise() += wake_influence(lambda);
  return a;
}

Eigen::VectorXcd VortexLattice::circulation(Complex lambda, const Eigen::VectorXcd& w, const Eigen::VectorXcd& dw_dx) const {
  return influence(lambda).partialPivLu().solve(lambda * w + U_ * dw_dx);
}

Eigen::VectorXcd VortexLattice::steady_force(const Eigen::VectorXcd& gamma) const { return -rho_ * U_ * gamma; }

Eigen::VectorXcd VortexLattice::unsteady_force(Complex lambda, const Eigen::VectorXcd& gamma) const {
  return lambda * (unsteady_.cast<Complex>() * gamma);
}

namespace {

// Hermite cubic shape functions on an element of length le at xi in [0, 1], for the degrees of
// freedom (w0, w0', w1, w1'): values, first and second derivatives in x.
struct Shape {
  Eigen::Vector4d n, dn, d2n;
};
Shape hermite(double xi, double le) {
  Shape s;
  s.n << 1 - 3 * xi * xi + 2 * xi * xi * xi, le * (xi - 2 * xi * xi + xi * xi * xi), 3 * xi * xi - 2 * xi * xi * xi,
      le * (-xi * xi + xi * xi * xi);
  s.dn << (-6 * xi + 6 * xi * xi) / le, 1 - 4 * xi + 3 * xi * xi, (6 * xi - 6 * xi * xi) / le, -2 * xi + 3 * xi * xi;
  s.d2n << (-6 + 12 * xi) / (le * le), (-4 + 6 * xi) / le, (6 - 12 * xi) / (le * le), (-2 + 6 * xi) / le;
  return s;
}

struct BeamModel {
  std::vector<double> nodes;
  Eigen::MatrixXd mass, stiffness;  // reduced (constraints applied)
  Eigen::MatrixXd constraint;       // full dofs = constraint * reduced dofs
  // Values (derivative 0) or slopes (1) at points, in reduced dofs.
  Eigen::MatrixXd interpolation(const std::vector<double>& xs, int derivative) const {
    Eigen::MatrixXd p = Eigen::MatrixXd::Zero(Eigen::Index(xs.size()), Eigen::Index(2 * nodes.size()));
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const auto it = std::upper_bound(nodes.begin(), nodes.end(), xs[i]);
      const std::size_t e = std::clamp<std::size_t>(std::size_t(it - nodes.begin()), 1, nodes.size() - 1) - 1;
      const double le = nodes[e + 1] - nodes[e];
      const Shape s = hermite((xs[i] - nodes[e]) / le, le);
      p.block(Eigen::Index(i), Eigen::Index(2 * e), 1, 4) = (derivative == 0 ? s.n : s.dn).transpose();
    }
    return p * constraint;
  }
};

BeamModel build_beam(const SlenderBody& body, int elements) {
  if (!(body.x_end > body.x_begin) || elements < 4) throw std::invalid_argument("flutter model: empty body or too few elements");
  BeamModel beam;
  const double rigid_end = std::clamp(body.rigid_until, body.x_begin, body.x_end);
  const double length = body.x_end - body.x_begin;
  const int rigid_elements = rigid_end > body.x_begin ? std::max(2, int(std::round(elements * (rigid_end - body.x_begin) / length))) : 0;
  for (int k = 0; k < rigid_elements; ++k) beam.nodes.push_back(body.x_begin + (rigid_end - body.x_begin) * k / rigid_elements);
  const int flexible_elements = std::max(2, elements - rigid_elements);
  for (int k = 0; k <= flexible_elements; ++k) beam.nodes.push_back(rigid_end + (body.x_end - rigid_end) * k / flexible_elements);
  const int n = int(beam.nodes.size());

  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(2 * n, 2 * n), stiffness = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  const double plate_modulus = body.youngs_modulus / (1.0 - body.poisson_ratio * body.poisson_ratio);  // plane strain
  // 6-point Gauss-Legendre on [0, 1]
  const double gx[6] = {0.033765242898423987, 0.16939530676686775, 0.38069040695840156,
                        0.61930959304159845, 0.83060469323313224, 0.96623475710157603};
  const double gw[6] = {0.085662246189585178, 0.18038078652406930, 0.23395696728634552,
                        0.23395696728634552, 0.18038078652406930, 0.085662246189585178};
  for (int e = 0; e + 1 < n; ++e) {
    const double le = beam.nodes[e + 1] - beam.nodes[e];
    for (int g = 0; g < 6; ++g) {
      const double x = beam.nodes[e] + gx[g] * le, h = body.thickness(x), weight = gw[g] * le;
      const Shape s = hermite(gx[g], le);
      mass.block(2 * e, 2 * e, 4, 4) += weight * body.solid_density * h * s.n * s.n.transpose();
      stiffness.block(2 * e, 2 * e, 4, 4) += weight * plate_modulus * h * h * h / 12.0 * s.d2n * s.d2n.transpose();
    }
  }
  // Constraints: the rigid part moves as w = w_nose + theta (x - x_begin); the support removes
  // w_nose (pinned), both (clamped), or keeps both (tethered, with a lateral spring at the nose).
  std::vector<Eigen::VectorXd> columns;
  const int rigid_nodes = rigid_elements > 0 ? rigid_elements + 1 : 1;  // the first node always belongs to the support
  Eigen::VectorXd heave = Eigen::VectorXd::Zero(2 * n), pitch = Eigen::VectorXd::Zero(2 * n);
  for (int k = 0; k < rigid_nodes; ++k) {
    heave(2 * k) = 1.0;
    pitch(2 * k) = beam.nodes[k] - body.x_begin;
    pitch(2 * k + 1) = 1.0;
  }
  if (body.support == NoseSupport::Tethered) columns.push_back(heave);
  if (body.support != NoseSupport::Clamped) columns.push_back(pitch);
  for (int k = rigid_nodes; k < n; ++k)
    for (int d = 0; d < 2; ++d) {
      Eigen::VectorXd c = Eigen::VectorXd::Zero(2 * n);
      c(2 * k + d) = 1.0;
      columns.push_back(c);
    }
  beam.constraint.resize(2 * n, Eigen::Index(columns.size()));
  for (std::size_t c = 0; c < columns.size(); ++c) beam.constraint.col(Eigen::Index(c)) = columns[c];
  beam.mass = beam.constraint.transpose() * mass * beam.constraint;
  beam.stiffness = beam.constraint.transpose() * stiffness * beam.constraint;
  if (body.support == NoseSupport::Tethered) beam.stiffness(0, 0) += body.lateral_stiffness;  // heave is reduced dof 0
  return beam;
}

struct Coupled {
  BeamModel beam;
  VortexLattice lattice;
  // The fluid's generalised forces without the wake, and what the wake's rank-one term needs:
  // with B1 = A_b^-1 P_c and B0 = A_b^-1 U P'_c (circulations per unit lambda w and per unit q), the
  // steady (S = -rho U P_v^T) and unsteady (N = P_m^T times the lattice's unsteady operator)
  // projections S B1, S B0, N B1, N B0, the column sums 1^T B1, 1^T B0, and S, N themselves.
  Eigen::PartialPivLU<Eigen::MatrixXd> bound_lu;
  Eigen::MatrixXd s_b1, s_b0, n_b1, n_b0, steady, unsteady;
  Eigen::RowVectorXd sum_b1, sum_b0;

  Coupled(BeamModel b, VortexLattice l) : beam(std::move(b)), lattice(std::move(l)), bound_lu(lattice.bound_influence()) {
    const Eigen::MatrixXd at_collocation = beam.interpolation(lattice.collocation_points(), 0);
    const Eigen::MatrixXd slope = beam.interpolation(lattice.collocation_points(), 1);
    steady = -lattice.fluid_density() * lattice.stream_speed() * beam.interpolation(lattice.vortex_points(), 0).transpose();
    unsteady = beam.interpolation(lattice.panel_centres(), 0).transpose() * lattice.unsteady_operator();
    const Eigen::MatrixXd b1 = bound_lu.solve(at_collocation), b0 = bound_lu.solve(lattice.stream_speed() * slope);
    s_b1 = steady * b1;
    s_b0 = steady * b0;
    n_b1 = unsteady * b1;
    n_b0 = unsteady * b0;
    sum_b1 = b1.colwise().sum();
    sum_b0 = b0.colwise().sum();
  }
};

// The quadratic eigenproblem lambda^2 M2 + lambda C2 + K2 with the wake evaluated at lambda_wake,
// linearised to the companion matrix [[0, I], [-M2^-1 K2, -M2^-1 C2]]. Circulations
// Gamma = G1 lambda q + G0 q with G = (A_b + w 1^T)^-1 (...): the wake enters by Sherman-Morrison,
// G = B - z (1^T B) / (1 + 1^T z), z = A_b^-1 w. Generalised force = S Gamma + lambda N Gamma.
Eigen::MatrixXcd frozen_wake_companion(const Coupled& c, Complex lambda_wake, bool with_fluid) {
  const Eigen::Index n = c.beam.mass.rows();
  Eigen::MatrixXcd m2 = c.beam.mass.cast<Complex>(), c2 = Eigen::MatrixXcd::Zero(n, n), k2 = c.beam.stiffness.cast<Complex>();
  if (with_fluid) {
    Eigen::MatrixXcd s_g1 = c.s_b1.cast<Complex>(), s_g0 = c.s_b0.cast<Complex>();
    Eigen::MatrixXcd n_g1 = c.n_b1.cast<Complex>(), n_g0 = c.n_b0.cast<Complex>();
    if (std::abs(lambda_wake) > 0.0) {
      const Eigen::VectorXcd w = c.lattice.wake_influence(lambda_wake);
      const Eigen::VectorXcd z = c.bound_lu.solve(w.real()).cast<Complex>() + Complex(0.0, 1.0) * c.bound_lu.solve(w.imag()).cast<Complex>();
      const Complex denominator = 1.0 + z.sum();
      const Eigen::VectorXcd s_z = c.steady * z / denominator, n_z = c.unsteady * z / denominator;
      s_g1 -= s_z * c.sum_b1.cast<Complex>();
      s_g0 -= s_z * c.sum_b0.cast<Complex>();
      n_g1 -= n_z * c.sum_b1.cast<Complex>();
      n_g0 -= n_z * c.sum_b0.cast<Complex>();
    }
    m2 -= n_g1;
    c2 -= s_g1 + n_g0;
    k2 -= s_g0;
  }
  Eigen::MatrixXcd companion = Eigen::MatrixXcd::Zero(2 * n, 2 * n);
  const auto m2_lu = m2.partialPivLu();
  companion.topRightCorner(n, n).setIdentity();
  companion.bottomLeftCorner(n, n) = -m2_lu.solve(k2);
  companion.bottomRightCorner(n, n) = -m2_lu.solve(c2);
  return companion;
}

Eigen::ComplexEigenSolver<Eigen::MatrixXcd> all_eigen(const Eigen::MatrixXcd& companion, bool vectors) {
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> solver(companion, vectors);
  if (solver.info() != Eigen::Success) throw std::runtime_error("flutter model: eigenvalue solver failed");
  return solver;
}

// The eigenvalue of `companion` nearest `shift`, by inverse iteration from the vector x (updated):
// y = (A - shift)^-1 x gives the estimate shift + x^H x / x^H y.
Complex nearest_eigenvalue(const Eigen::MatrixXcd& companion, Complex shift, Eigen::VectorXcd& x) {
  const Eigen::Index n = companion.rows();
  const Complex sigma = shift + 1e-9 * std::max(1.0, std::abs(shift));  // never exactly on an eigenvalue
  const auto lu = (companion - sigma * Eigen::MatrixXcd::Identity(n, n)).partialPivLu();
  Complex estimate = shift;
  for (int k = 0; k < 20; ++k) {
    const Eigen::VectorXcd y = lu.solve(x);
    const Complex next = sigma + x.squaredNorm() / x.dot(y);
    x = y / y.norm();
    const bool settled = std::abs(next - estimate) < 1e-12 * std::abs(next);
    estimate = next;
    if (settled) break;
  }
  return estimate;
}

std::vector<Complex> ascending_frequency(std::vector<Complex> v) {
  std::sort(v.begin(), v.end(), [](Complex a, Complex b) { return a.imag() < b.imag(); });
  return v;
}

}  // namespace

double FlutterModes::largest_growth(double max_frequency) const {
  double g = -INFINITY;
  for (const Complex& l : wetted)
    if (l.imag() <= two_pi * max_frequency) g = std::max(g, l.real());
  return g;
}

FlutterModes flutter_modes(const SlenderBody& body, const FlowModel& flow, double max_frequency) {
  const Coupled c(build_beam(body, flow.elements),
                  VortexLattice(body.x_begin, body.x_end, flow.panels, flow.stream_speed, flow.fluid_density));

  FlutterModes out;
  const double omega_max = two_pi * max_frequency;
  const auto in_vacuo = all_eigen(frozen_wake_companion(c, 0.0, false), false);
  for (const Complex& l : in_vacuo.eigenvalues())
    if (l.imag() > 1e-8 && l.imag() <= omega_max) out.in_vacuo.push_back(l);
  out.in_vacuo = ascending_frequency(out.in_vacuo);

  // Roots are followed from starting points: the roots of the problem with the wake frozen at
  // lambda = 0 (quasi-steady) and at i omega for each in-vacuo frequency (harmonic wake), so that a
  // mode the quasi-steady problem misplaces is still reached. From each, a fixed-point iteration on
  // the wake: lambda <- the frozen-wake eigenvalue nearest lambda (inverse iteration from the
  // previous eigenvector). Oscillatory roots and growing real roots (divergence) are followed;
  // decaying real roots lie on the wake's branch cut and are not modes.
  std::vector<Complex> wake_samples = {0.0};
  for (const Complex& l : out.in_vacuo) wake_samples.emplace_back(0.0, l.imag());
  std::vector<std::pair<Complex, Eigen::VectorXcd>> starts;
  for (const Complex& sample : wake_samples) {
    const auto frozen = all_eigen(frozen_wake_companion(c, sample, true), true);
    for (Eigen::Index k = 0; k < frozen.eigenvalues().size(); ++k) {
      const Complex start = frozen.eigenvalues()(k);
      const bool oscillatory = start.imag() > 1e-8 && start.imag() <= 1.5 * omega_max;
      const bool diverging = std::abs(start.imag()) <= 1e-8 && start.real() > 0.0;
      if (oscillatory || diverging) starts.emplace_back(start, frozen.eigenvectors().col(k));
    }
  }
  for (auto& [start, start_vector] : starts) {
    // A start next to a root already found would only find it again.
    const Complex s0 = start;
    if (std::any_of(out.wetted.begin(), out.wetted.end(), [&](Complex w) { return std::abs(w - s0) < 1e-2 * std::abs(s0); })) continue;
    Complex lambda = start;
    Eigen::VectorXcd vector = start_vector;
    bool converged = false;
    try {
      // A root is a fixed point of g(lambda) = the frozen-wake eigenvalue nearest lambda; the secant
      // method on g(lambda) - lambda finds it in a few steps where plain iteration needs dozens.
      Complex previous = lambda, previous_residual = 0.0;
      for (int iteration = 0; iteration < 60 && !converged; ++iteration) {
        const Complex residual = nearest_eigenvalue(frozen_wake_companion(c, lambda, true), lambda, vector) - lambda;
        // The eigenvalues' round-off here is about 1e-7 (measured: the residual stalls at 1e-9 - 1e-7).
        converged = std::abs(residual) < 1e-6 * std::max(1.0, std::abs(lambda));
        if (converged) break;
        const Complex slope = iteration == 0 ? Complex(-1.0) : (residual - previous_residual) / (lambda - previous);
        previous = lambda;
        previous_residual = residual;
        lambda -= residual / slope;
      }
    } catch (const std::runtime_error&) {
      // The iteration ran onto the wake's branch cut (a decaying non-oscillatory root): not a mode.
    }
    if (!converged) { ++out.unconverged; continue; }
    if (lambda.imag() < -1e-8 || lambda.imag() > omega_max) continue;
    const bool known = std::any_of(out.wetted.begin(), out.wetted.end(),
                                   [&](Complex w) { return std::abs(w - lambda) < 1e-4 * std::max(1.0, std::abs(lambda)); });
    if (!known) out.wetted.push_back(lambda);
  }
  out.wetted = ascending_frequency(out.wetted);
  return out;
}

std::optional<double> critical_youngs_modulus(SlenderBody body, const FlowModel& flow, double max_frequency, double low,
                                              double high) {
  auto growth = [&](double e) {
    body.youngs_modulus = e;
    return flutter_modes(body, flow, max_frequency).largest_growth(max_frequency);
  };
  double g_low = growth(low), g_high = growth(high);
  if (!(g_low > 0.0) || !(g_high < 0.0)) return std::nullopt;  // soft end must flutter, stiff end must not
  // Bisection in log E to 1 %.
  while (high / low > 1.01) {
    const double mid = std::sqrt(low * high);
    (growth(mid) > 0.0 ? low : high) = mid;
  }
  return std::sqrt(low * high);
}

}  // namespace mrsph::verification::theory
