#include "fluid/acoustic_step.hpp"

#include "core/parallel.hpp"
#include "fluid/density_diffusion.hpp"

#include <algorithm>

namespace mrsph {

void advance_density_and_position(FluidBody& fluid, Real dt_density, Real dt_position) {
  FluidParticles& f = fluid.particles;
  const EquationOfState& eos = fluid.material.eos;
  parallel_for_each(f.size(), [&](std::size_t i) {
    f.rho[i] += dt_density * f.drho_dt[i];
    f.p[i] = eos.pressure(f.rho[i]);
    f.vol[i] = f.mass[i] / f.rho[i];
    f.pos[i] += dt_position * f.vel[i];
  }, kGrainSimpleLoop);
}

namespace {

// v_i += dt ((f^p + f^d + F^prior) / m + g); an open boundary's buffer keeps its imposed velocity.
void kick_particle(FluidParticles& f, std::size_t i, Real dt, const Vec2& body_acceleration) {
  if (!f.in_domain(i)) return;
  f.vel[i] += dt * ((f.pressure_force[i] + f.dissipation_force[i] + f.force_prior[i]) / f.mass[i] + body_acceleration);
}

}  // namespace

void advance_position(FluidBody& fluid, Real dt) {
  FluidParticles& f = fluid.particles;
  parallel_for_each(f.size(), [&](std::size_t i) { f.pos[i] += dt * f.vel[i]; }, kGrainSimpleLoop);
}

void compute_pressure_interaction(FluidBody& fluid, const NeighborList& inner, std::vector<FluidContact>& contacts,
                                  const Vec2& body_acceleration, Real kick_dt) {
  FluidParticles& f = fluid.particles;
  const RiemannDissipation& riemann = fluid.riemann;
  for (FluidContact& c : contacts) c.pair_pressure_force.resize(c.pairs.pair_count());
  const Real scale = fluid.options.pressure_lattice_correction ? 1.0 / fluid.lattice_gradient : 1.0;
  const Real delta = fluid.options.delta_sph;
  const Real diffusion_scale = delta * fluid.h() * fluid.material.sound_speed();
  compute_renormalised_density_gradient(fluid, inner);

  parallel_for_each(f.size(), [&](std::size_t i) {
    const Real p_i = f.p[i], rho_i = f.rho[i], vol_i = f.vol[i];
    const Real p_i_relative = p_i - 2.0 * fluid.reference_pressure;  // p_i + p_j - 2 p_ref
    const Real vol_i_scaled = scale * vol_i;
    Vec2 force = Vec2::Zero();
    Real drho = 0.0, diffusion = 0.0;
    for (const Neighbor& n : inner.of(i)) {
      force -= (vol_i_scaled * f.vol[n.j] * (p_i_relative + f.p[n.j]) * n.dW) * n.e;
      if (riemann.continuity) drho += f.vol[n.j] * riemann.continuity_term(p_i, f.p[n.j]) * n.dW;
      if (delta != 0.0)
        diffusion += density_diffusion_pair(rho_i, f.rho[n.j], fluid.density_gradient[i], fluid.density_gradient[n.j],
                                            f.vol[n.j], n);
    }
    const Vec2 acc_prior = f.force_prior[i] / f.mass[i] + body_acceleration;
    for (FluidContact& c : contacts) {
      const RealArray& vol = *c.boundary.vol;
      const Vec2Array& abar = *c.boundary.acc_ave;
      const Index first = c.pairs.offset(i);
      const auto list = c.pairs.of(i);
      for (std::size_t k = 0; k < list.size(); ++k) {
        const Neighbor& n = list[k];
        const Vec2 r_ai = -n.r * n.e;  // r_a - r_i
        const Real p_d = p_i + rho_i * std::max(Real(0), (acc_prior - abar[n.j]).dot(r_ai));
        const Vec2 pair = -(vol_i_scaled * vol[n.j] * (p_i_relative + p_d) * n.dW) * n.e;
        c.pair_pressure_force[first + k] = pair;
        force += pair;
        if (riemann.continuity) drho += vol[n.j] * riemann.continuity_term(p_i, p_d) * n.dW;
      }
    }
    f.pressure_force[i] = force;
    f.drho_dt[i] = rho_i * drho + diffusion_scale * diffusion;
    // No particle reads another's velocity here: the kick can follow particle by particle.
    if (kick_dt != 0.0) kick_particle(f, i, kick_dt, body_acceleration);
  });
}

void kick(FluidBody& fluid, Real dt, const Vec2& body_acceleration) {
  FluidParticles& f = fluid.particles;
  parallel_for_each(f.size(), [&](std::size_t i) { kick_particle(f, i, dt, body_acceleration); }, kGrainSimpleLoop);
}

void add_velocity_divergence_and_dissipation(FluidBody& fluid, const NeighborList& inner,
                                             std::vector<FluidContact>& contacts, Real position_dt, Real density_dt) {
  FluidParticles& f = fluid.particles;
  const RiemannDissipation& riemann = fluid.riemann;
  for (FluidContact& c : contacts)
    c.pair_dissipation_force.assign(riemann.momentum ? c.pairs.pair_count() : 0, Vec2::Zero());

  parallel_for_each(f.size(), [&](std::size_t i) {
    // No particle reads another's position or density here: both updates follow particle by particle.
    if (position_dt != 0.0) f.pos[i] += position_dt * f.vel[i];
    const Vec2 v_i = f.vel[i];
    const Real vol_i = f.vol[i];
    Real divergence = 0.0;
    Vec2 dissipation = Vec2::Zero();
    for (const Neighbor& n : inner.of(i)) {
      const Real u = (v_i - f.vel[n.j]).dot(n.e);
      divergence += f.vol[n.j] * u * n.dW;
      if (riemann.momentum) dissipation += (vol_i * f.vol[n.j] * riemann.momentum_coefficient(u) * n.dW) * n.e;
    }
    for (FluidContact& c : contacts) {
      const RealArray& vol = *c.boundary.vol;
      const Vec2Array& vbar = *c.boundary.vel_ave;
      const Vec2Array& normal = *c.boundary.normal;
      const Index first = c.pairs.offset(i);
      const auto list = c.pairs.of(i);
      for (std::size_t k = 0; k < list.size(); ++k) {
        const Neighbor& n = list[k];
        const Vec2 relative = v_i - vbar[n.j];
        divergence += vol[n.j] * 2.0 * relative.dot(n.e) * n.dW;
        if (riemann.momentum) {
          const Vec2 n_f = n.e.dot(normal[n.j]) >= 0.0 ? normal[n.j] : Vec2(-normal[n.j]);
          const Real u = 2.0 * relative.dot(n_f);
          const Vec2 pair = (vol_i * vol[n.j] * riemann.momentum_coefficient(u) * n.dW) * n_f;
          c.pair_dissipation_force[first + k] = pair;
          dissipation += pair;
        }
      }
    }
    f.drho_dt[i] += f.rho[i] * divergence;
    f.dissipation_force[i] = dissipation;
    if (density_dt != 0.0) f.rho[i] += density_dt * f.drho_dt[i];
  });

  for (FluidContact& c : contacts) {
    c.boundary_dissipation_reaction.assign(c.pairs_of_boundary.size(), Vec2::Zero());
    if (riemann.momentum) accumulate_boundary_reaction(c, c.pair_dissipation_force, c.boundary_dissipation_reaction);
  }
}

void acoustic_first_half(FluidBody& fluid, const NeighborList& inner, std::vector<FluidContact>& contacts, Real dt,
                         const Vec2& body_acceleration) {
  advance_density_and_position(fluid, 0.5 * dt, 0.5 * dt);
  compute_pressure_interaction(fluid, inner, contacts, body_acceleration, dt);
}

void acoustic_second_half(FluidBody& fluid, const NeighborList& inner, std::vector<FluidContact>& contacts, Real dt) {
  add_velocity_divergence_and_dissipation(fluid, inner, contacts, 0.5 * dt, 0.5 * dt);
}

void accumulate_boundary_reaction(const FluidContact& contact, const Vec2Array& pair_force, Vec2Array& reaction) {
  parallel_for_each(contact.pairs_of_boundary.size(), [&](std::size_t a) {
    Vec2 sum = Vec2::Zero();
    for (Index k : contact.pairs_of_boundary.of(a)) sum -= pair_force[k];
    reaction[a] += sum;
  });
}

}  // namespace mrsph
