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

// p_ref of FluidOptions::pressure_reference: the mean over the particles (equal masses: the
// mass-weighted mean), summed in particle order so that runs stay bitwise reproducible.
void update_reference_pressure(FluidBody& fluid) {
  if (fluid.options.pressure_reference != PressureReference::Mean || fluid.particles.size() == 0) {
    fluid.reference_pressure = 0.0;
    return;
  }
  const FluidParticles& f = fluid.particles;
  Real mass = 0.0, weighted = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    mass += f.mass[i];
    weighted += f.mass[i] * fluid.material.eos.pressure(f.rho[i]);
  }
  fluid.reference_pressure = weighted / mass;
}

}  // namespace

void reinitialise_density(FluidBody& fluid, const NeighborList& inner, const std::vector<FluidContact>& contacts,
                          Real relaxation) {
  FluidParticles& f = fluid.particles;
  const Real rho0 = fluid.material.rho0();
  const bool free_surface = fluid.options.density == DensityReinitialisation::FreeSurface;
  if (fluid.options.density == DensityReinitialisation::None) {  // the continuity equation's density stays
    update_reference_pressure(fluid);
    return;
  }
  parallel_for_each(f.size(), [&](std::size_t i) {
    Real rho = summation_density(fluid, inner, contacts, i);
    if (free_surface) rho = std::max(rho, rho0);
    if (relaxation != 1.0) rho = f.rho[i] + relaxation * (rho - f.rho[i]);
    f.rho[i] = rho;
    f.vol[i] = f.mass[i] / rho;
  });
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
