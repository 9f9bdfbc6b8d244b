#include "fluid/acoustic_step.hpp"

#include "core/parallel.hpp"
#include "fluid/density_diffusion.hpp"
#include "fluid/wall_rules.hpp"
#include "interaction/pair_sweep.hpp"

#include <algorithm>
#include <type_traits>

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

namespace {

// A pair as the pressure pass reads it: j, dW, r_i - r_j, and the kernel gradient as a scale times a
// vector: dW e as cached at the list build, or (dW / r) r_ij at the current positions.
struct CachedGeometry {
  const Neighbor& n;
  Index j() const { return n.j; }
  Real dW() const { return n.dW; }
  Real gradient_scale() const { return n.dW; }
  Vec2 gradient_vector() const { return n.e; }
  Vec2 r_ij() const { return n.r * Vec2(n.e); }
  const Neighbor& neighbor() const { return n; }
};
// A fluid-boundary pair at the current positions: the fluid particle moved by moved_i since the list
// build, the boundary particle by its own displacement (none for a boundary that never moves).
MovedPair contact_pair_now(const FluidContact& c, const Neighbor& cached, const Vec2& moved_i) {
  return c.pairs.moved(cached, moved_i, c.boundary.pos == nullptr ? Vec2::Zero() : c.boundary_moved[cached.j]);
}

struct MovedGeometry {
  MovedPair m;
  Index j() const { return m.j; }
  Real dW() const { return m.dW; }
  Real gradient_scale() const { return m.dW_over_r; }
  const Vec2& gradient_vector() const { return m.r_ij; }
  const Vec2& r_ij() const { return m.r_ij; }
  Neighbor neighbor() const { return m.as_neighbor(); }
};

// The pressure pair force's form: the plain sum (p_i + p_j - 2 p_ref) with a constant p_ref (Zero,
// Mean); each side's pressure with its kernel-gradient correction
// (FluidOptions::pressure_gradient_correction); the plain sum on p - p_ref(x) with p_ref linear in x
// (PressureReference::Linear), plus the exact -V_i grad p_ref (reference_pressure.hpp).
enum class PairPressure { Plain, Corrected, LinearReference };

// f^p_i (Eqs. 28, 21, 30) and the density rate's pressure-difference part (the Riemann term, or the
// delta-SPH diffusion D_i of density_diffusion.hpp); then, with kick_dt != 0, the kick. kRefresh: the
// pair geometry at the current positions (FluidOptions::refresh_pair_geometry), else as cached.
template <bool kRefresh, PairPressure kForm>
struct PressureInteraction {
  static constexpr bool kCorrected = kForm == PairPressure::Corrected;
  static constexpr bool kLinear = kForm == PairPressure::LinearReference;
  // Particle i's values, read once (a boundary pair's force is stored in the pair loop, after which
  // the compiler could not assume i's arrays unchanged), and its sums.
  struct Sum {
    Real p, rho;
    Real p_relative;      // p_i - 2 p_ref(r_i): the pair forces use p_i + p_j - 2 p_ref(r_i) + grad p_ref . r_ij
    Real vol_scaled;      // V_i, divided by FluidBody::gradient_moment with the pressure lattice correction
    Vec2 acc_beyond_rest;  // F^prior_i / m_i + g - g_rest: the wall pressure's clipped acceleration
    Vec2 moved;           // r_i - r_i at the list build (kRefresh)
    Mat2 correction;      // B_i (kCorrected)
    Vec2 force = Vec2::Zero();
    Real drho = 0.0, diffusion = 0.0;
  };
  struct Side {
    const RealArray& vol;
    const Vec2Array& abar;
    Vec2Array& pair_force;
    const FluidContact& contact;
  };

  FluidBody& fluid;
  FluidParticles& f;
  std::vector<FluidContact>& contacts;
  const Vec2& body_acceleration;
  Real kick_dt;
  const NeighborList& inner_list;
  Real scale = fluid.options.pressure_lattice_correction && !kCorrected ? 1.0 / fluid.gradient_moment : 1.0;
  Real delta = fluid.options.delta_sph;
  Real diffusion_scale = delta * fluid.h() * fluid.material.sound_speed();
  Vec2 rest_gradient = fluid.riemann.rest_pressure_gradient(body_acceleration);
  bool at_rest_state = rest_gradient != Vec2::Zero();  // the continuity term on the departure from it
  // The rest state the wall rule continues whole (FluidOptions::rest_state_at_walls; wall_rules.hpp),
  // else none: the paper's clip of the whole acceleration.
  bool walls_at_rest_state = fluid.options.rest_state_at_walls;
  Vec2 wall_rest_gradient = walls_at_rest_state ? rest_gradient : Vec2::Zero();
  Vec2 acceleration_beyond_rest =
      body_acceleration - (walls_at_rest_state ? fluid.riemann.rest_acceleration(body_acceleration) : Vec2::Zero());

  Sum begin(std::size_t i) const {
    return {f.p[i], f.rho[i], f.p[i] - 2.0 * (kLinear ? fluid.reference.at(f.pos[i]) : fluid.reference.level), scale * f.vol[i],
            f.force_prior[i] / f.mass[i] + acceleration_beyond_rest,
            kRefresh ? fluid.moved_since_list_build[i] : Vec2::Zero(),
            kCorrected ? fluid.gradient_correction[i] : Mat2::Identity()};
  }

  // -V_i V_j dW times (p_i + p_j - 2 p_ref) e; with a linear p_ref, (p_i - p_ref(r_i)) + (p_j - p_ref(r_j))
  // = p_i + p_j - 2 p_ref(r_i) + grad p_ref . r_ij; or with each side's correction
  // ((p_i - p_ref) B_i + (p_j - p_ref) B_j) e (kCorrected).
  template <class Geometry>
  Vec2 pair_force(const Sum& s, Real vol_j, Real p_j, const Mat2& correction_j, const Geometry& g) const {
    if constexpr (kCorrected) {
      const Vec2& e = g.gradient_vector();
      return -(s.vol_scaled * vol_j * g.gradient_scale()) *
             ((s.p_relative + fluid.reference.level) * (s.correction * e) + (p_j - fluid.reference.level) * (correction_j * e));
    } else {
      Real p_sum = s.p_relative + p_j;
      if constexpr (kLinear) p_sum += fluid.reference.gradient.dot(g.r_ij());
      return -(s.vol_scaled * vol_j * p_sum * g.gradient_scale()) * g.gradient_vector();
    }
  }

  // The pair's geometry at the current positions (kRefresh).
  MovedGeometry current_inner_pair(const Sum& s, const Neighbor& cached) const {
    return {inner_list.moved(cached, s.moved, fluid.moved_since_list_build[cached.j])};
  }
  MovedGeometry current_contact_pair(const Sum& s, const FluidContact& c, const Neighbor& cached) const {
    return {contact_pair_now(c, cached, s.moved)};
  }

  void inner(Sum& s, std::size_t i, const Neighbor& cached) const {
    if constexpr (kRefresh) inner_pair_force(s, i, current_inner_pair(s, cached));
    else inner_pair_force(s, i, CachedGeometry{cached});
  }

  template <class Geometry>
  void inner_pair_force(Sum& s, std::size_t i, const Geometry& g) const {
    const Index j = g.j();
    s.force += pair_force(s, f.vol[j], f.p[j], kCorrected ? fluid.gradient_correction[j] : s.correction, g);
    if (fluid.riemann.continuity) s.drho += f.vol[j] * continuity_term(s.p, f.p[j], g) * g.dW();
    if (delta != 0.0)
      s.diffusion += density_diffusion_pair(s.rho, f.rho[j], fluid.density_gradient[i], fluid.density_gradient[j],
                                            f.vol[j], g.neighbor());
  }

  Side boundary(std::size_t c) const {
    return {*contacts[c].boundary.vol, *contacts[c].boundary.acc_ave, contacts[c].pair_pressure_force, contacts[c]};
  }

  void contact(Sum& s, std::size_t, const Side& b, Index k, const Neighbor& cached) const {
    if constexpr (kRefresh) contact_pair_force(s, b, k, current_contact_pair(s, b.contact, cached));
    else contact_pair_force(s, b, k, CachedGeometry{cached});
  }

  template <class Geometry>
  void contact_pair_force(Sum& s, const Side& b, Index k, const Geometry& g) const {
    const Index a = g.j();
    const Real p_d = wall_pressure(s.p, s.rho, s.acc_beyond_rest, b.abar[a], -g.r_ij(), wall_rest_gradient);
    const Vec2 pair = pair_force(s, b.vol[a], p_d, s.correction, g);
    b.pair_force[k] = pair;
    s.force += pair;
    if (fluid.riemann.continuity) s.drho += b.vol[a] * continuity_term(s.p, p_d, g) * g.dW();
  }

  template <class Geometry>
  Real continuity_term(Real p_i, Real p_j, const Geometry& g) const {
    return at_rest_state ? fluid.riemann.continuity_term(p_i, p_j, rest_gradient, g.r_ij())
                         : fluid.riemann.continuity_term(p_i, p_j);
  }

  void finish(std::size_t i, const Sum& s) const {
    if constexpr (kLinear) f.pressure_force[i] = s.force - f.vol[i] * fluid.reference.gradient;
    else f.pressure_force[i] = s.force;
    f.drho_dt[i] = s.rho * s.drho + diffusion_scale * s.diffusion;
    // No particle reads another's velocity here: the kick can follow particle by particle.
    if (kick_dt != 0.0) kick_particle(f, i, kick_dt, body_acceleration);
  }
};

// drho/dt += rho_i div v (Eq. 27 and its wall term); f^d (the Riemann momentum dissipation). Before,
// where non-zero: r += position_dt v; after: rho += density_dt drho/dt (no particle reads another's
// position or density here). kRefresh: the pair geometry at the positions after that move
// (FluidOptions::refresh_divergence_geometry; the fluid's displacements measured before the sweep, a
// moving boundary's as the pressure pass measured them), else as cached.
template <bool kRefresh>
struct DivergenceAndDissipation {
  struct Sum {
    Vec2 v;    // v_i, read once (as in PressureInteraction)
    Real vol;  // V_i
    Vec2 moved;  // r_i - r_i at the list build, after this pass's move (kRefresh)
    Real divergence = 0.0;
    Vec2 dissipation = Vec2::Zero();
  };
  struct Side {
    const RealArray& vol;
    const Vec2Array& vbar;
    const Vec2Array& normal;
    Vec2Array& pair_force;
    const FluidContact& contact;
  };

  FluidParticles& f;
  const RiemannDissipation& riemann;
  std::vector<FluidContact>& contacts;
  Real position_dt, density_dt;
  bool mirrored_wall_continuity;
  const NeighborList& inner_list;
  const Vec2Array& moved;  // FluidBody::moved_since_list_build (kRefresh)

  Sum begin(std::size_t i) const {
    if (position_dt != 0.0) f.pos[i] += position_dt * f.vel[i];
    return {f.vel[i], f.vol[i], kRefresh ? moved[i] : Vec2::Zero()};
  }

  void inner(Sum& s, std::size_t i, const Neighbor& cached) const {
    if constexpr (kRefresh) inner_pair(s, i, inner_list.moved(cached, s.moved, moved[cached.j]).as_neighbor());
    else inner_pair(s, i, cached);
  }

  void inner_pair(Sum& s, std::size_t, const Neighbor& n) const {
    const Real u = (s.v - f.vel[n.j]).dot(n.e);
    s.divergence += f.vol[n.j] * u * n.dW;
    if (riemann.momentum) s.dissipation += (s.vol * f.vol[n.j] * riemann.momentum_coefficient(u) * n.dW) * n.e;
  }

  Side boundary(std::size_t c) const {
    const FluidContact& contact = contacts[c];
    return {*contact.boundary.vol, *contact.boundary.vel_ave, *contact.boundary.normal,
            contacts[c].pair_dissipation_force, contact};
  }

  void contact(Sum& s, std::size_t i, const Side& b, Index k, const Neighbor& cached) const {
    if constexpr (kRefresh) contact_pair(s, i, b, k, contact_pair_now(b.contact, cached, s.moved).as_neighbor());
    else contact_pair(s, i, b, k, cached);
  }

  void contact_pair(Sum& s, std::size_t, const Side& b, Index k, const Neighbor& n) const {
    s.divergence += b.vol[n.j] * wall_continuity_velocity_difference(s.v, b.vbar[n.j], mirrored_wall_continuity).dot(n.e) * n.dW;
    if (!riemann.momentum) return;
    const Vec2 difference = wall_velocity_difference(s.v, b.vbar[n.j]);
    const Vec2 n_f = wall_normal_towards_fluid(n.e, b.normal[n.j]);
    const Real u = difference.dot(n_f);
    const Vec2 pair = (s.vol * b.vol[n.j] * riemann.momentum_coefficient(u) * n.dW) * n_f;
    b.pair_force[k] = pair;
    s.dissipation += pair;
  }

  void finish(std::size_t i, const Sum& s) const {
    f.drho_dt[i] += f.rho[i] * s.divergence;
    f.dissipation_force[i] = s.dissipation;
    if (density_dt != 0.0) f.rho[i] += density_dt * f.drho_dt[i];
  }
};

// r + position_dt v - r at the list build of the fluid's particles: where the continuity pass will have
// moved them (refresh_divergence_geometry).
void measure_fluid_displacements_after_move(FluidBody& fluid, Real position_dt) {
  const FluidParticles& f = fluid.particles;
  fluid.moved_since_list_build.resize(f.size());
  parallel_for_each(f.size(), [&](std::size_t i) {
    fluid.moved_since_list_build[i] = f.pos[i] + position_dt * f.vel[i] - fluid.positions_at_list_build[i];
  }, kGrainSimpleLoop);
}

// r - r at the list build of the moving boundaries' particles (refresh_pair_geometry,
// refresh_divergence_geometry: the solids move beside the continuity pass, so both read them here).
void measure_boundary_displacements_since_list_build(std::vector<FluidContact>& contacts) {
  for (FluidContact& c : contacts) {
    if (c.boundary.pos == nullptr) continue;
    c.boundary_moved.resize(c.boundary.pos->size());
    for (std::size_t a = 0; a < c.boundary_moved.size(); ++a)
      c.boundary_moved[a] = (*c.boundary.pos)[a] - c.boundary_positions_at_list_build[a];
  }
}

}  // namespace

void compute_pressure_interaction(FluidBody& fluid, const NeighborList& inner, std::vector<FluidContact>& contacts,
                                  const Vec2& body_acceleration, Real kick_dt) {
  for (FluidContact& c : contacts) c.pair_pressure_force.resize(c.pairs.pair_count());
  compute_renormalised_density_gradient(fluid, inner);
  const auto sweep = [&](auto interaction) { sweep_with_contacts(inner, contacts, interaction); };
  const auto sweep_in_form = [&](auto refresh) {
    constexpr bool kRefresh = decltype(refresh)::value;
    if (fluid.options.pressure_gradient_correction)
      sweep(PressureInteraction<kRefresh, PairPressure::Corrected>{fluid, fluid.particles, contacts, body_acceleration, kick_dt, inner});
    else if (fluid.options.pressure_reference == PressureReference::Linear)
      sweep(PressureInteraction<kRefresh, PairPressure::LinearReference>{fluid, fluid.particles, contacts, body_acceleration, kick_dt, inner});
    else
      sweep(PressureInteraction<kRefresh, PairPressure::Plain>{fluid, fluid.particles, contacts, body_acceleration, kick_dt, inner});
  };
  if (fluid.options.refreshes_pair_geometry()) measure_boundary_displacements_since_list_build(contacts);
  if (fluid.options.refresh_pair_geometry) {
    measure_fluid_displacements_after_move(fluid, 0.0);
    sweep_in_form(std::true_type{});
  } else {
    sweep_in_form(std::false_type{});
  }
}

void kick(FluidBody& fluid, Real dt, const Vec2& body_acceleration) {
  FluidParticles& f = fluid.particles;
  parallel_for_each(f.size(), [&](std::size_t i) { kick_particle(f, i, dt, body_acceleration); }, kGrainSimpleLoop);
}

void add_velocity_divergence_and_dissipation(FluidBody& fluid, const NeighborList& inner,
                                             std::vector<FluidContact>& contacts, Real position_dt, Real density_dt,
                                             Sharing sharing) {
  const RiemannDissipation& riemann = fluid.riemann;
  for (FluidContact& c : contacts)
    c.pair_dissipation_force.assign(riemann.momentum ? c.pairs.pair_count() : 0, Vec2::Zero());
  const auto sweep = [&](auto refresh) {
    sweep_with_contacts(inner, contacts,
                        DivergenceAndDissipation<decltype(refresh)::value>{
                            fluid.particles, riemann, contacts, position_dt, density_dt,
                            fluid.options.mirrored_wall_continuity, inner, fluid.moved_since_list_build},
                        sharing);
  };
  if (fluid.options.refresh_divergence_geometry) {
    measure_fluid_displacements_after_move(fluid, position_dt);
    sweep(std::true_type{});
  } else {
    sweep(std::false_type{});
  }
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

void acoustic_second_half(FluidBody& fluid, const NeighborList& inner, std::vector<FluidContact>& contacts, Real dt,
                          Sharing sharing) {
  add_velocity_divergence_and_dissipation(fluid, inner, contacts, 0.5 * dt, 0.5 * dt, sharing);
}

void accumulate_boundary_reaction(const FluidContact& contact, const Vec2Array& pair_force, Vec2Array& reaction) {
  parallel_for_each(contact.pairs_of_boundary.size(), [&](std::size_t a) {
    Vec2 sum = Vec2::Zero();
    for_each_pair_of_target(contact.pairs_of_boundary, a, [&](Index k) { sum -= pair_force[k]; });
    reaction[a] += sum;
  });
}

}  // namespace mrsph
