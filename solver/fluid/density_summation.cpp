#include "fluid/density_summation.hpp"

#include "core/parallel.hpp"
#include "interaction/pair_sweep.hpp"

#include <algorithm>
#include <limits>

namespace mrsph {

namespace {

// sum_j W_ij m_j / rho0 over the fluid and sum_a W_ia V_a over the boundaries, with i's own W(0).
struct KernelSum {
  struct Side {
    const RealArray& vol;
    const NeighborList& pairs;
  };
  const FluidParticles& f;
  const NeighborList& inner_list;
  const std::vector<FluidContact>& contacts;
  Real rho0;

  void inner(Real& sum, std::size_t, const Neighbor& n) const { sum += inner_list.W(n) * f.mass[n.j] / rho0; }
  Side boundary(std::size_t c) const { return {*contacts[c].boundary.vol, contacts[c].pairs}; }
  void contact(Real& sum, std::size_t, const Side& b, Index, const Neighbor& n) const {
    sum += b.pairs.W(n) * b.vol[n.j];
  }
};

// sum_j V_j r_ij dW_ij over the fluid and the boundaries, at the volumes the pressure pass reads.
struct MomentSum {
  struct Side {
    const RealArray& vol;
  };
  const FluidParticles& f;
  const std::vector<FluidContact>& contacts;

  void inner(Real& sum, std::size_t, const Neighbor& n) const { sum += f.vol[n.j] * n.r * n.dW; }
  Side boundary(std::size_t c) const { return {*contacts[c].boundary.vol}; }
  void contact(Real& sum, std::size_t, const Side& b, Index, const Neighbor& n) const {
    sum += b.vol[n.j] * n.r * n.dW;
  }
};

// sum_j V_j grad W_ij (x) (r_j - r_i) = -sum_j V_j r_ij dW_ij e_ij (x) e_ij over the fluid and the
// boundaries (symmetric), at the volumes and the cached geometry the pressure pass reads.
struct GradientMomentTensor {
  struct Side {
    const RealArray& vol;
  };
  const FluidParticles& f;
  const std::vector<FluidContact>& contacts;

  static Mat2 term(Real vol, const Neighbor& n) {
    const Vec2 e = n.e;
    return (-vol * n.r * n.dW) * (e * e.transpose());
  }
  void inner(Mat2& sum, std::size_t, const Neighbor& n) const { sum += term(f.vol[n.j], n); }
  Side boundary(std::size_t c) const { return {*contacts[c].boundary.vol}; }
  void contact(Mat2& sum, std::size_t, const Side& b, Index, const Neighbor& n) const { sum += term(b.vol[n.j], n); }
};

// FluidBody::gradient_correction: B_i = A_i^-1; 1 / M1 of the square lattice instead in an open
// boundary's buffer (whose far rows have their supports cut by the buffer's end, not by a wall) and
// where the support is cut so far that A_i is nearly singular (det below a quarter of the lattice's).
void measure_gradient_correction(FluidBody& fluid, const NeighborList& inner, const std::vector<FluidContact>& contacts) {
  const FluidParticles& f = fluid.particles;
  fluid.gradient_correction.resize(f.size());
  const Real m1 = fluid.lattice_gradient;
  parallel_for_each(f.size(), [&](std::size_t i) {
    if (!f.in_domain(i)) {
      fluid.gradient_correction[i] = Mat2::Identity() / m1;
      return;
    }
    Mat2 sum = Mat2::Zero();
    GradientMomentTensor op{f, contacts};
    visit_with_contacts(inner, contacts, i, op, sum);
    fluid.gradient_correction[i] = sum.determinant() > 0.25 * m1 * m1 ? Mat2(sum.inverse()) : Mat2(Mat2::Identity() / m1);
  });
}

// A support counts as full where the kernel sum reaches 99.7 % of the square lattice's (Wendland C2,
// h = 1.3 dp, lattice sums): under a free surface the top row has 78.6 % (moment 0.625) and the row
// below 99.51 % (moment 0.937, 4 % under the full 0.974), while a hexagonal arrangement of the same
// number density at rest has 99.84 % (moment 0.985), and a compressed fluid more.
constexpr Real kFullSupport = 0.997;

// FluidBody::gradient_moment with FluidOptions::measured_pressure_moment: the mean over the particles
// whose kernel support is full (rho_sum >= kFullSupport rho0) of the isotropic first
// moment m_i = -1/2 sum_j V_j r_ij dW_ij (kernel/lattice_moments.hpp's M1 on the square lattice, 0.985
// on the hexagonal one), summed in particle order (bitwise reproducible); the lattice's M1 if none is.
void measure_gradient_moment(FluidBody& fluid, const NeighborList& inner, const std::vector<FluidContact>& contacts,
                             const std::vector<char>& full_support) {
  const FluidParticles& f = fluid.particles;
  std::vector<Real> moment(f.size(), 0.0);
  parallel_for_each(f.size(), [&](std::size_t i) {
    if (!full_support[i]) return;
    Real sum = 0.0;
    MomentSum op{f, contacts};
    visit_with_contacts(inner, contacts, i, op, sum);
    moment[i] = -0.5 * sum;
  });
  Real total = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < f.size(); ++i)
    if (full_support[i]) {
      total += moment[i];
      ++count;
    }
  fluid.gradient_moment = count > 0 ? total / static_cast<Real>(count) : fluid.lattice_gradient;
}

Real summation_density(const FluidBody& fluid, const NeighborList& inner, const std::vector<FluidContact>& contacts,
                       std::size_t i) {
  const FluidParticles& f = fluid.particles;
  const Real rho0 = fluid.material.rho0();
  const Real v0_i = f.mass[i] / rho0;
  Real sum = fluid.kernel.W0() * v0_i;
  KernelSum op{f, inner, contacts, rho0};
  visit_with_contacts(inner, contacts, i, op, sum);
  return rho0 / fluid.lattice_number_density * sum / v0_i;
}

}  // namespace

Real density_relaxation_per_step(const FluidOptions& options) {
  return options.density_relaxation * options.paper_step_fraction();
}

void reinitialise_density(FluidBody& fluid, const NeighborList& inner, const std::vector<FluidContact>& contacts,
                          Real relaxation) {
  FluidParticles& f = fluid.particles;
  const Real rho0 = fluid.material.rho0();
  const bool free_surface = fluid.options.density == DensityReinitialisation::FreeSurface;
  if (fluid.options.density == DensityReinitialisation::None) {  // the continuity equation's density stays
    if (fluid.options.pressure_gradient_correction) measure_gradient_correction(fluid, inner, contacts);
    update_reference_pressure(fluid);
    return;
  }
  const bool measure = fluid.options.measured_pressure_moment && fluid.options.pressure_lattice_correction;
  std::vector<char> full_support(measure ? f.size() : 0);
  parallel_for_each(f.size(), [&](std::size_t i) {
    Real rho = summation_density(fluid, inner, contacts, i);
    if (measure) full_support[i] = rho >= kFullSupport * rho0;
    if (free_surface) rho = std::max(rho, rho0);
    if (relaxation != 1.0) rho = f.rho[i] + relaxation * (rho - f.rho[i]);
    f.rho[i] = rho;
    f.vol[i] = f.mass[i] / rho;
  });
  if (measure) measure_gradient_moment(fluid, inner, contacts, full_support);
  if (fluid.options.pressure_gradient_correction) measure_gradient_correction(fluid, inner, contacts);
  update_reference_pressure(fluid);
}

Real smallest_support_fraction(const FluidBody& fluid, const NeighborList& inner,
                               const std::vector<FluidContact>& contacts) {
  const Real rho0 = fluid.material.rho0();
  return -parallel_max(fluid.particles.size(), [&](std::size_t i) {
    return -summation_density(fluid, inner, contacts, i) / rho0;
  }, -std::numeric_limits<Real>::infinity());
}

}  // namespace mrsph
