// Linear flutter theory of a slender flexible body in a uniform two-dimensional potential flow: a
// reference answer for the passive fish (paper section 4.4) that does not come from SPH.
//
// The body is an Euler-Bernoulli beam along x (plane strain: bending stiffness E h^3 / (12 (1 - nu^2))
// and mass rho_S h per unit length, h(x) the local thickness) whose front part is rigid, held at its
// nose (clamped, pinned, or on a cable that gives it a lateral stiffness). The fluid is inviscid and
// linearised about a uniform stream U: the body is a thin vortex sheet on its centre line with the
// Kutta condition at the trailing edge and a wake convected at U (unsteady thin-aerofoil theory, the
// model of Kornecki, Dowell & O'Brien 1976 and Eloy, Souilliez & Schouveiler 2007 in two dimensions).
// Small motions w(x) e^{lambda t} solve a nonlinear eigenproblem in lambda; Re(lambda) > 0 is flutter
// (or divergence). Left out: viscosity, the body's thickness in the flow, channel walls, shear.
//
// Discretisation: Hermite cubic beam elements; a vortex lattice with cosine-spaced panels (vortex at
// the panel's quarter point, collocation at three quarters, which imposes the Kutta condition) and
// the wake integrated exactly with the exponential integral. Checked against Theodorsen's function
// (tests/test_plate_flutter.cpp).
#pragma once

#include <Eigen/Dense>

#include <complex>
#include <functional>
#include <optional>
#include <vector>

namespace mrsph::verification::theory {

using Complex = std::complex<double>;

// The fluid side: a lattice of vortex panels on [x_begin, x_end] in a stream U along +x.
class VortexLattice {
 public:
  VortexLattice(double x_begin, double x_end, int panels, double stream_speed, double fluid_density);

  int panels() const { return int(vortex_.size()); }
  const std::vector<double>& vortex_points() const { return vortex_; }
  const std::vector<double>& collocation_points() const { return collocation_; }
  const std::vector<double>& panel_centres() const { return centre_; }

  // The matrix that maps the panels' circulations to the lateral velocity they and their wake induce at
  // the collocation points, for motions proportional to e^{lambda t}.
  Eigen::MatrixXcd influence(Complex lambda) const;
  // Its two parts: the bound vortices' (real, independent of lambda) and the wake's, which is the
  // same for every panel's circulation (the wake carries the total): influence = bound + wake 1^T.
  const Eigen::MatrixXd& bound_influence() const { return bound_; }
  Eigen::VectorXcd wake_influence(Complex lambda) const;
  // Panel circulations for the motion: the fluid's lateral velocity at the collocation points equals
  // the body's, dw/dt + U dw/dx = lambda w + U w'.
  Eigen::VectorXcd circulation(Complex lambda, const Eigen::VectorXcd& w, const Eigen::VectorXcd& dw_dx) const;
  // Upward force on each panel from the pressure jump (linearised unsteady Bernoulli):
  // steady part -rho U Gamma_i at the vortex point, unsteady part -rho lambda int Gamma dx at the centre.
  Eigen::VectorXcd steady_force(const Eigen::VectorXcd& gamma) const;
  Eigen::VectorXcd unsteady_force(Complex lambda, const Eigen::VectorXcd& gamma) const;
  // The unsteady force is lambda * unsteady_operator() * gamma.
  const Eigen::MatrixXd& unsteady_operator() const { return unsteady_; }
  double stream_speed() const { return U_; }
  double fluid_density() const { return rho_; }

 private:
  double U_, rho_, x_end_;
  std::vector<double> vortex_, collocation_, centre_;
  Eigen::MatrixXd bound_;     // 1 / (2 pi (x_c,i - x_v,j))
  Eigen::MatrixXd unsteady_;  // -rho width_i (sum_{j<i} Gamma_j + Gamma_i / 2)
};

// How the body is held at its nose.
enum class NoseSupport { Clamped, Pinned, Tethered };

struct SlenderBody {
  std::function<double(double)> thickness;  // full thickness h(x), x from the nominal nose
  double x_begin = 0.0, x_end = 1.0;         // the body's extent (thin ends dropped)
  double rigid_until = 0.0;                  // x < rigid_until moves rigidly
  double solid_density = 1.0;
  double youngs_modulus = 1.0;
  double poisson_ratio = 0.0;
  NoseSupport support = NoseSupport::Pinned;
  double lateral_stiffness = 0.0;            // Tethered: cable tension / cable length, at x_begin
};

struct FlowModel {
  double stream_speed = 1.0;
  double fluid_density = 1.0;
  int panels = 200;
  int elements = 40;
};

struct FlutterModes {
  std::vector<Complex> in_vacuo;  // lambda without fluid, Im > 0, ascending frequency
  std::vector<Complex> wetted;    // lambda with fluid, Im >= 0, ascending frequency
  int unconverged = 0;            // starts whose iteration did not settle (reported, not hidden)
  // Largest growth rate Re(lambda) among the wetted modes up to a frequency.
  double largest_growth(double max_frequency) const;
};

// The modes of the body in the flow up to max_frequency (Hz, i.e. Im lambda / 2 pi).
FlutterModes flutter_modes(const SlenderBody& body, const FlowModel& flow, double max_frequency);

// The Young's modulus below which the straight body flutters (largest growth rate crosses zero),
// searched on [low, high]; nullopt if the sign does not change on that interval.
std::optional<double> critical_youngs_modulus(SlenderBody body, const FlowModel& flow, double max_frequency, double low,
                                              double high);

}  // namespace mrsph::verification::theory
