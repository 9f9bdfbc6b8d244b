#include "boundary/open_boundary.hpp"

#include "core/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mrsph {

namespace {

std::uint8_t zone_of(std::size_t k) { return static_cast<std::uint8_t>(k + 1); }

// The bins along the plane (width dp) and the bin of a position.
struct PlaneBins {
  int tangent;
  Real lower, width;
  std::size_t count;
  PlaneBins(const OpenBoundary& b, Real dp)
      : tangent(1 - b.axis), lower(b.span_lower), width(dp),
        count(std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil((b.span_upper - b.span_lower) / dp)))) {}
  std::size_t index_of(const Vec2& p) const {
    const Real k = std::floor((p[tangent] - lower) / width);
    return static_cast<std::size_t>(std::clamp<Real>(k, 0.0, static_cast<Real>(count - 1)));
  }
};

// Extrapolation from the domain's particles within one kernel support of the plane (the band):
// per bin, the mean velocity, pressure and depth (an empty bin takes its nearest non-empty one);
// over the whole band, the sums for a least-squares line of the pressure against depth.
struct BandMeans {
  Vec2Array vel;
  RealArray p, depth;
  Real n = 0, sum_d = 0, sum_dd = 0, sum_p = 0, sum_dp = 0;

  // The pressure gradient along the outward normal: least squares through the band, or through
  // the band and the point (0, p_plane) when the plane's pressure is prescribed.
  Real slope() const { return n < 2 ? 0.0 : (sum_dp - sum_d * sum_p / n) / std::max(sum_dd - sum_d * sum_d / n, 1e-300); }
  Real slope_through(Real p_plane) const { return n < 1 ? 0.0 : (sum_dp - p_plane * sum_d) / sum_dd; }
};

// A domain particle within one kernel support inside the plane: the band the buffer reads.
bool in_band(const FluidBody& fluid, const OpenBoundary& b, std::size_t i) {
  if (!fluid.particles.in_domain(i)) return false;
  const Real d = b.depth(fluid.particles.pos[i]);
  return d <= 0.0 && d > -fluid.kernel.cutoff();
}

BandMeans domain_band_means(const FluidBody& fluid, const OpenBoundary& b, const PlaneBins& bins) {
  const FluidParticles& f = fluid.particles;
  BandMeans m{Vec2Array(bins.count, Vec2::Zero()), RealArray(bins.count, 0.0), RealArray(bins.count, 0.0)};
  std::vector<int> count(bins.count, 0);
  for (std::size_t i = 0; i < f.size(); ++i) {  // in particle order: bitwise reproducible
    if (!in_band(fluid, b, i)) continue;
    const Real d = b.depth(f.pos[i]);
    const std::size_t k = bins.index_of(f.pos[i]);
    m.vel[k] += f.vel[i];
    m.p[k] += f.p[i];
    m.depth[k] += d;
    ++count[k];
    m.n += 1;
    m.sum_d += d;
    m.sum_dd += d * d;
    m.sum_p += f.p[i];
    m.sum_dp += d * f.p[i];
  }
  // An empty bin (next to a wall, or where the flow left a gap) reads its nearest non-empty bin:
  // the nearest from below and from above, the nearer of the two (below on a tie).
  const long none = -1, bin_count = static_cast<long>(bins.count);
  std::vector<long> below(bins.count, none), above(bins.count, none), source(bins.count, none);
  for (long k = 0, last = none; k < bin_count; ++k) below[k] = last = count[k] > 0 ? k : last;
  for (long k = bin_count - 1, last = none; k >= 0; --k) above[k] = last = count[k] > 0 ? k : last;
  for (long k = 0; k < bin_count; ++k)
    source[k] = above[k] == none || (below[k] != none && k - below[k] <= above[k] - k) ? below[k] : above[k];
  for (std::size_t k = 0; k < bins.count; ++k)
    if (count[k] > 0) {
      m.vel[k] /= count[k];
      m.p[k] /= count[k];
      m.depth[k] /= count[k];
    }
  BandMeans filled = m;
  for (std::size_t k = 0; k < bins.count; ++k)
    if (source[k] != none) {
      filled.vel[k] = m.vel[source[k]];
      filled.p[k] = m.p[source[k]];
      filled.depth[k] = m.depth[source[k]];
    }
  return filled;
}

// The normal velocity of the band's particles fitted by least squares with the Legendre polynomials
// P0..P4 of the tangential coordinate mapped to [-1, 1] over the span, evaluated at each bin's
// centre (header). Fewer band particles than terms: the bins' means.
RealArray smoothed_normal_velocity(const FluidBody& fluid, const OpenBoundary& b, const PlaneBins& bins,
                                   const BandMeans& means) {
  constexpr int kTerms = 5;
  using Basis = Eigen::Matrix<Real, kTerms, 1>;
  const auto basis = [&](Real tangential) {
    const Real s = 2.0 * (tangential - b.span_lower) / (b.span_upper - b.span_lower) - 1.0;
    Basis p;
    p[0] = 1.0;
    p[1] = s;
    for (int k = 1; k + 1 < kTerms; ++k) p[k + 1] = ((2 * k + 1) * s * p[k] - k * p[k - 1]) / (k + 1);  // Bonnet
    return p;
  };
  const FluidParticles& f = fluid.particles;
  Eigen::Matrix<Real, kTerms, kTerms> normal_matrix = Eigen::Matrix<Real, kTerms, kTerms>::Zero();
  Basis rhs = Basis::Zero();
  int count = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {  // in particle order: bitwise reproducible
    if (!in_band(fluid, b, i)) continue;
    const Basis p = basis(f.pos[i][bins.tangent]);
    normal_matrix += p * p.transpose();
    rhs += p * f.vel[i].dot(b.normal());
    ++count;
  }
  RealArray u_n(bins.count);
  if (count < kTerms) {
    for (std::size_t k = 0; k < bins.count; ++k) u_n[k] = means.vel[k].dot(b.normal());
    return u_n;
  }
  const Basis coefficients = normal_matrix.partialPivLu().solve(rhs);
  for (std::size_t k = 0; k < bins.count; ++k)
    u_n[k] = basis(bins.lower + (static_cast<Real>(k) + 0.5) * bins.width).dot(coefficients);
  return u_n;
}

// rho0 u_n^2 / 2 where the fluid enters (u_n < 0 along the outward normal), else 0: the drop from
// the total pressure p_b of fluid drawn from rest to its static pressure at the plane (header).
Real entering_dynamic_pressure(Real rho0, Real u_n) { return u_n < 0.0 ? 0.5 * rho0 * u_n * u_n : 0.0; }

// ubar_n of the weakly reflecting condition, relaxed towards u_n over tau (exact for a constant
// u_n over the step); set to u_n on first use.
void relax_mean_normal_velocity(OpenBoundary& b, const BandMeans& means, Real dt) {
  const std::size_t n = means.vel.size();
  const bool first = b.mean_normal_velocity.size() != n;
  if (first) b.mean_normal_velocity.assign(n, 0.0);
  const Real weight = first ? 1.0 : 1.0 - std::exp(-dt / b.reflection_time);
  for (std::size_t k = 0; k < n; ++k) {
    const Real u_n = means.vel[k].dot(b.normal());
    b.mean_normal_velocity[k] += weight * (u_n - b.mean_normal_velocity[k]);
  }
}

// Fills the space the flow opened at the buffer's far end: in each bin along the plane where the
// buffer moves towards the plane, new particles behind the outermost one (copies of it), at the
// spacing along the normal at which particles of mass m have the buffer's density:
// dx = m / (rho dp). A lattice of spacing dp would stand for rho0 in the density summation, not for
// the buffer's pressure.
void refill_buffer(FluidBody& fluid, OpenBoundary& b, std::size_t k, const std::vector<bool>& removed) {
  FluidParticles& f = fluid.particles;
  const PlaneBins bins(b, fluid.dp);
  std::vector<std::size_t> outermost(bins.count, f.size());
  const std::uint8_t zone = zone_of(k);
  for (std::size_t i = 0; i < removed.size(); ++i) {
    if (f.zone[i] != zone || removed[i]) continue;
    std::size_t& o = outermost[bins.index_of(f.pos[i])];
    if (o == f.size() || b.depth(f.pos[i]) > b.depth(f.pos[o])) o = i;
  }
  for (std::size_t bin = 0; bin < bins.count; ++bin) {
    std::size_t last = outermost[bin];
    if (last >= removed.size()) continue;  // no buffer particle in this bin: nothing to continue
    // Only where the buffer moves towards the plane does its far end empty; where it moves out (an
    // outflow), the far end is where particles leave, and a refill would only make particles that
    // are deleted a step later.
    if (f.vel[last].dot(b.normal()) >= 0.0) continue;
    for (;;) {
      const Real dx = f.mass[last] / (f.rho[last] * fluid.dp);
      // A density outside (rho0 / 2, 2 rho0), or not a number, is a diverging run (the divergence
      // check that follows reports it): refill nothing rather than loop.
      if (!(dx > 0.5 * fluid.dp && dx < 2.0 * fluid.dp)) break;
      if (b.depth(f.pos[last]) + dx > b.width) break;
      f.append_copy_of(last);
      f.pos.back() += dx * b.normal();
      last = f.size() - 1;
      ++b.ledger.created;
    }
  }
}

}  // namespace

void classify_fluid_zones(FluidParticles& fluid, const std::vector<OpenBoundary>& boundaries) {
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    fluid.zone[i] = kDomainZone;
    for (std::size_t k = 0; k < boundaries.size(); ++k)
      if (boundaries[k].depth(fluid.pos[i]) > 0.0) fluid.zone[i] = zone_of(k);
  }
}

void exchange_buffer_particles(FluidBody& fluid, std::vector<OpenBoundary>& boundaries) {
  FluidParticles& f = fluid.particles;
  std::vector<bool> remove(f.size(), false);
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f.in_domain(i)) {
      for (std::size_t k = 0; k < boundaries.size(); ++k)
        if (boundaries[k].depth(f.pos[i]) > 0.0) {
          f.zone[i] = zone_of(k);
          boundaries[k].ledger.mass_into_domain -= f.mass[i];
          break;
        }
    } else if (OpenBoundary& b = boundaries[f.zone[i] - 1]; b.depth(f.pos[i]) <= 0.0) {
      f.zone[i] = kDomainZone;
      b.ledger.mass_into_domain += f.mass[i];
    }
    if (!f.in_domain(i)) {
      OpenBoundary& b = boundaries[f.zone[i] - 1];
      if (b.depth(f.pos[i]) > b.width) {
        remove[i] = true;
        ++b.ledger.deleted;
      }
    }
  }
  for (std::size_t k = 0; k < boundaries.size(); ++k) refill_buffer(fluid, boundaries[k], k, remove);
  remove.resize(f.size(), false);
  f.erase(remove);
}

void impose_buffer_states(FluidBody& fluid, std::vector<OpenBoundary>& boundaries, Real t, Real dt) {
  FluidParticles& f = fluid.particles;
  const EquationOfState& eos = fluid.material.eos;
  for (std::size_t k = 0; k < boundaries.size(); ++k) {
    OpenBoundary& b = boundaries[k];
    const PlaneBins bins(b, fluid.dp);
    BandMeans means = domain_band_means(fluid, b, bins);
    if (b.condition == OpenBoundaryCondition::Pressure && b.smooth_normal_velocity) {
      const RealArray u_n = smoothed_normal_velocity(fluid, b, bins, means);
      for (std::size_t bin = 0; bin < bins.count; ++bin) means.vel[bin] = u_n[bin] * b.normal();
    }
    const bool reflecting = b.condition == OpenBoundaryCondition::Velocity || b.reflection_time <= 0.0;
    if (!reflecting) relax_mean_normal_velocity(b, means, dt);
    // Pressure condition: the pressure at the plane in each bin, p_b or, weakly reflecting,
    // p_b + rho0 c (u_n - ubar_n); the slope of the continuation goes through their mean.
    RealArray plane_p;
    Real slope = means.slope();
    if (b.condition == OpenBoundaryCondition::Pressure) {
      const Real p_b = b.pressure(t);
      plane_p.assign(bins.count, p_b);
      if (!reflecting)
        for (std::size_t bin = 0; bin < bins.count; ++bin)
          plane_p[bin] += eos.impedance() * (means.vel[bin].dot(b.normal()) - b.mean_normal_velocity[bin]);
      if (b.total_pressure_inflow)
        for (std::size_t bin = 0; bin < bins.count; ++bin)
          plane_p[bin] -= entering_dynamic_pressure(eos.rho0, means.vel[bin].dot(b.normal()));
      slope = means.slope_through(std::accumulate(plane_p.begin(), plane_p.end(), 0.0) / static_cast<Real>(bins.count));
    }
    const std::uint8_t zone = zone_of(k);
    parallel_for_each(f.size(), [&](std::size_t i) {
      if (f.zone[i] != zone) return;
      const std::size_t bin = bins.index_of(f.pos[i]);
      const Real depth = b.depth(f.pos[i]);
      if (b.condition == OpenBoundaryCondition::Velocity) {
        f.vel[i] = inflow_velocity(b.velocity, f.pos[i], t);
        f.p[i] = means.p[bin] + slope * (depth - means.depth[bin]);
      } else {
        f.vel[i] = means.vel[bin].dot(b.normal()) * b.normal();
        f.p[i] = plane_p[bin] + slope * depth;
      }
      f.rho[i] = eos.density(f.p[i]);
      f.vol[i] = f.mass[i] / f.rho[i];
      f.drho_dt[i] = 0.0;
    }, kGrainSimpleLoop);
  }
}

Real domain_mass(const FluidParticles& fluid) {
  Real mass = 0.0;
  for (std::size_t i = 0; i < fluid.size(); ++i)
    if (fluid.in_domain(i)) mass += fluid.mass[i];
  return mass;
}

}  // namespace mrsph
