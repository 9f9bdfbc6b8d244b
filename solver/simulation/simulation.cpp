#include "simulation/simulation.hpp"

#include "core/errors.hpp"
#include "core/parallel.hpp"
#include "fluid/density_summation.hpp"
#include "fluid/transport_velocity.hpp"
#include "geometry/particle_normals.hpp"
#include "solid/solid_dynamics.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <sstream>
#include <stdexcept>

namespace mrsph {

void Simulation::set_fluid(FluidBody fluid) {
  if (initialised_) throw std::logic_error("Simulation: bodies must be added before initialise()");
  fluid_.emplace(std::move(fluid));
}

WallBody& Simulation::add_wall(WallBody wall) {
  if (initialised_) throw std::logic_error("Simulation: bodies must be added before initialise()");
  walls_.push_back(std::move(wall));
  return walls_.back();
}

SolidBody& Simulation::add_solid(SolidBody solid) {
  if (initialised_) throw std::logic_error("Simulation: bodies must be added before initialise()");
  solids_.push_back(std::move(solid));
  return solids_.back();
}

std::optional<std::size_t> Simulation::solid_index(const std::string& name) const {
  for (std::size_t s = 0; s < solids_.size(); ++s)
    if (solids_[s].name == name) return s;
  return std::nullopt;
}

void Simulation::initialise() {
  if (initialised_) throw std::logic_error("Simulation: initialise() called twice");
  initialised_ = true;

  for (WallBody& wall : walls_) {
    CellGrid grid(box_, wall.kernel.cutoff());
    grid.build(wall.particles.pos);
    NeighborList inner;
    inner.build(wall.particles.pos, grid, wall.kernel, /*exclude_self=*/true);
    wall.particles.normal = normals_from_kernel_gradient(wall.particles.vol, inner);
    wall.particles.depth = depths_below_surface(wall.particles.normal, inner, wall.dp, wall.kernel.cutoff());
  }
  // Bodies in contact first: their gradient weights depend on it (initialise_solid).
  for (SolidContact& contact : solid_contacts) {
    if (contact.second_is_wall) {
      if (contact.first >= solids_.size() || contact.second >= walls_.size())
        throw std::logic_error("Simulation: a wall contact must join a solid body and a wall");
      solids_[contact.first].in_contact = true;
      continue;
    }
    if (contact.first >= solids_.size() || contact.second >= solids_.size() || contact.first == contact.second)
      throw std::logic_error("Simulation: a solid contact must join two different solid bodies");
    solids_[contact.first].in_contact = solids_[contact.second].in_contact = true;
  }
  for (SolidBody& solid : solids_) initialise_solid(solid);
  for (SolidContact& contact : solid_contacts) {
    if (contact.second_is_wall) {
      const WallBody& wall = walls_[contact.second];
      prepare_wall_contact(contact, solids_[contact.first], wall.particles, wall.dp);
    } else {
      prepare_solid_contact(contact, solids_[contact.first], solids_[contact.second]);
    }
  }

  if (!fluid_) return;
  for (const WallBody& wall : walls_) {
    FluidContact c;
    c.boundary_name = wall.name;
    c.boundary = wall.boundary_view();
    contacts_.push_back(std::move(c));
  }
  for (const SolidBody& solid : solids_) {
    FluidContact c;
    c.boundary_name = solid.name;
    c.boundary = solid.boundary_view();
    contacts_.push_back(std::move(c));
  }
  classify_fluid_zones(fluid_->particles, open_boundaries);
  resolve_automatic_fluid_options();
  share_linear_reference_with_immersed_bodies();
  rebuild_fluid_relations();
  relax_fluid_particles();
  reinitialise_density(*fluid_, fluid_inner_, contacts_, 1.0);  // the initial density: the arrangement's
  FluidParticles& f = fluid_->particles;
  for (std::size_t i = 0; i < f.size(); ++i) f.p[i] = fluid_->material.eos.pressure(f.rho[i]);
  if (!open_boundaries.empty()) impose_buffer_states(*fluid_, open_boundaries, time, 0.0);
}

Vec2 Simulation::fluid_body_acceleration(Real t) const {
  const Vec2 g = body_force.at(t);
  return inflow && box_.periodic[0] ? Vec2(g + inflow->channel_acceleration(t)) : g;
}

void Simulation::impose_boundary_states(Real dt) {
  if (!fluid_) return;
  if (dt > 0.0 && inflow) inflow->apply(fluid_->particles, time, box_);
  if (!open_boundaries.empty()) impose_buffer_states(*fluid_, open_boundaries, time, dt);
}

void Simulation::exchange_open_boundary_particles() {
  if (fluid_ && !open_boundaries.empty()) exchange_buffer_particles(*fluid_, open_boundaries);
}

namespace {

// Orders fluid particles by cell (row-major over cells of size `cell`) so that neighbours sit
// close in memory. Particle identity is not tracked anywhere, so the fluid may be reordered.
std::vector<Index> cell_order(const Vec2Array& pos, const DomainBox& box, Real cell) {
  const std::size_t n = pos.size();
  std::vector<std::int64_t> key(n);
  Vec2 lo = pos.empty() ? Vec2::Zero() : pos[0];
  for (const Vec2& p : pos) lo = lo.cwiseMin(box.wrap(p));
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 q = (box.wrap(pos[i]) - lo) / cell;
    key[i] = static_cast<std::int64_t>(q.y()) * 1000000 + static_cast<std::int64_t>(q.x());
  }
  std::vector<Index> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return key[a] < key[b]; });
  return order;
}

constexpr std::size_t kSortInterval = 100;  // advection steps between reorderings

// A free surface under gravity: a column whose pressure, rho g depth, is large against the flow's
// own, and whose summation density is reset each advection step from an arrangement that a free
// surface cuts. Measured on the still tank, H/dp = 40 (reports/pressure.md sections 9-14): the
// paper's options leave the pressure 24 % of rho g H noisy and 2.8 % high at the floor; these take
// it to 1.2 % and 0.8 %. The gate against its experiment moves by under 0.1 mm at resolution ratios
// 1-2; at 4-8 the relaxed summation kept the trace of the coupling's bursts in the density, moving
// the loading phase by up to 1.6 mm, until the gate's damping went to 0.1 (reports/antoci.md).
//   - the summation's reset relaxed to 5 % per advection step: its arrangement noise (section 11);
//   - the pressure force divided by its lattice moment M1: the column held up by its gradient (6);
//   - the pressure pass's geometry at each acoustic step: a cached one feeds energy into the
//     particle motion in proportion to the pressure (section 9);
//   - the rest state rho0 g continued into the walls' dummies, and the pressure force divided by
//     the moment of the column's own arrangement, not the square lattice's: the tank within 0.5 %
//     at H/dp = 20, 40 and 80, a submerged body's buoyancy +0.3 to +1.8 % where the paper's clip
//     gives +2.2 to +4.1 % (sections 18 and 19).
constexpr Real kFreeSurfaceDensityRelaxation = 0.05;

void use_free_surface_defaults(FluidOptions& o) {
  if (o.left_to_flow.density_relaxation) o.density_relaxation = kFreeSurfaceDensityRelaxation;
  if (o.left_to_flow.pressure_lattice_correction) o.pressure_lattice_correction = true;
  if (o.left_to_flow.refresh_pair_geometry) o.refresh_pair_geometry = true;
  if (o.left_to_flow.rest_state_at_walls) o.rest_state_at_walls = true;
  if (o.left_to_flow.measured_pressure_moment) o.measured_pressure_moment = true;
}

}  // namespace

void Simulation::resolve_automatic_fluid_options() {
  FluidOptions& o = fluid_->options;
  // Gravity along an axis that is not periodic pulls the fluid onto a floor under open space: a
  // free surface. A constant force along a periodic axis drives a confined flow (a channel, an
  // array of bodies), and a fluid without one is confined by its walls. The kernel supports of
  // the initial particles cannot tell these apart: a lattice cut by a slanted or curved wall
  // leaves particles as empty (74-84 % filled) as the top row under a free surface (79 %).
  bool gravity_on_open_axis = false;
  for (int axis = 0; axis < 2; ++axis)
    if (!box_.periodic[axis] && body_force.constant[axis] != 0.0) gravity_on_open_axis = true;
  if (o.density == DensityReinitialisation::Automatic)
    o.density = gravity_on_open_axis ? DensityReinitialisation::FreeSurface : DensityReinitialisation::Internal;
  // An open boundary sets the pressure level (a pressure condition, or the fluid beyond an inlet):
  // the pressure is absolute, as under a free surface.
  const bool confined = (o.density == DensityReinitialisation::Internal ||
                         (o.density == DensityReinitialisation::None && !gravity_on_open_axis)) &&
                        open_boundaries.empty();
  if (o.pressure_reference == PressureReference::Automatic)
    o.pressure_reference = confined ? PressureReference::Mean : PressureReference::Zero;
  if (o.density == DensityReinitialisation::FreeSurface && o.pressure_gradient_correction)
    throw InputError("", "fluid.pressure_gradient_correction",
                     "expected false for a fluid with a free surface (gravity along a non-periodic axis, or "
                     "density_reinitialisation free_surface): the correction needs full kernel supports, which a free surface cuts");
  if (o.pressure_reference == PressureReference::Linear && o.density == DensityReinitialisation::FreeSurface)
    throw InputError("", "fluid.pressure_reference",
                     "expected \"zero\" or \"automatic\" for a fluid with a free surface (gravity along a non-periodic axis, "
                     "or density_reinitialisation free_surface), got \"linear\": at a free surface the pressure is absolute (0 is the atmosphere)");
  if (o.pressure_reference == PressureReference::Linear && o.pressure_gradient_correction)
    throw InputError("", "fluid.pressure_reference",
                     "expected \"linear\" without fluid.pressure_gradient_correction: both remove the pressure level's stress, "
                     "by different pair forces; choose one");
  if (o.density == DensityReinitialisation::FreeSurface) use_free_surface_defaults(o);
  // The continuity equation's wall term follows what defines the density (wall_rules.hpp).
  if (o.left_to_flow.mirrored_wall_continuity) o.mirrored_wall_continuity = o.density == DensityReinitialisation::None;
  fluid_->riemann.set_periodic_axes(box_.periodic[0], box_.periodic[1]);
  fluid_->non_periodic_axes = Vec2(box_.periodic[0] ? 0.0 : 1.0, box_.periodic[1] ? 0.0 : 1.0);
}

void Simulation::share_linear_reference_with_immersed_bodies() {
  if (fluid_->options.pressure_reference != PressureReference::Linear) return;
  // Immersed: every elastic solid (a beam, a leaflet, a fish: in the fluid, or fastened to a wall,
  // whose clamp takes the fastened face's load), and a wall whose particles all lie within the
  // bounding box of the fluid's (a cylinder in a channel), where a wall that bounds the fluid lies
  // outside it.
  const auto box_of = [](const Vec2Array& pos) {
    Eigen::AlignedBox<Real, 2> box;
    for (const Vec2& x : pos) box.extend(x);
    return box;
  };
  const auto fluid_box = box_of(fluid_->particles.pos);
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    const bool immersed = k >= walls_.size() || fluid_box.contains(box_of(walls_[k].particles.pos));
    if (immersed) contacts_[k].reference_gradient = &fluid_->reference.gradient;
  }
}

void Simulation::relax_fluid_particles() {
  // Coefficient and step limit of the relaxation: alpha = 0.25 as the transport-velocity correction
  // of the internal-flow scenes; a particle moves at most a tenth of a spacing per shift, so none
  // jumps a wall or solid layer before the shifts from its new neighbours can push it back.
  constexpr Real kAlpha = 0.25, kMaxShiftOverDp = 0.1;
  if (const Real amplitude = fluid_->options.relaxation_perturbation * fluid_->dp; amplitude > 0.0) {
    std::mt19937_64 generator(20261203);  // fixed seed: the same perturbation on every run
    std::uniform_real_distribution<Real> offset(-amplitude, amplitude);
    for (Vec2& p : fluid_->particles.pos) {
      const Real dx = offset(generator);
      p += Vec2(dx, offset(generator));
    }
    rebuild_fluid_relations();
  }
  for (int k = 0; k < fluid_->options.relaxation_steps; ++k) {
    shift_towards_uniform_distribution(*fluid_, fluid_inner_, contacts_, kAlpha, kMaxShiftOverDp * fluid_->dp);
    rebuild_fluid_relations();
  }
}

void Simulation::rebuild_fluid_relations() {
  if (!fluid_) return;
  FluidBody& fluid = *fluid_;
  FluidParticles& f = fluid.particles;
  parallel_for_each(f.size(), [&](std::size_t i) { f.pos[i] = box_.wrap(f.pos[i]); }, kGrainSimpleLoop);
  if (rebuilds_since_sort_++ % kSortInterval == 0) f.permute(cell_order(f.pos, box_, fluid.kernel.cutoff()));
  build_pair_lists();
}

void Simulation::restore_relations(std::size_t rebuild_count) {
  rebuilds_since_sort_ = rebuild_count;
  if (fluid_) build_pair_lists();
}

void Simulation::build_pair_lists() {
  FluidBody& fluid = *fluid_;
  FluidParticles& f = fluid.particles;
  // Cell lists of every body (the fixed walls' once, the others from current positions), then all
  // pair lists in one joint build.
  CellGrid fluid_grid(box_, fluid.kernel.cutoff());
  fluid_grid.build(f.pos);
  // One grid and kernel per contact, in the contacts' order (walls, then solids: initialise());
  // across a contact the larger h of the two bodies.
  const auto contact_kernel = [&](Real h_boundary) { return WendlandC2(std::max(fluid.h(), h_boundary)); };
  if (wall_grids_.size() != walls_.size()) {  // walls never move: their cell lists are built once
    wall_grids_.clear();
    for (const WallBody& wall : walls_) {
      wall_grids_.emplace_back(box_, contact_kernel(wall.h()).cutoff());
      wall_grids_.back().build(wall.particles.pos);
    }
  }
  std::vector<CellGrid> solid_grids;
  solid_grids.reserve(solids_.size());  // the requests below point into it
  std::vector<ListRequest> lists{{&fluid_inner_, &fluid_grid, fluid.kernel, /*exclude_self=*/true}};
  for (std::size_t w = 0; w < walls_.size(); ++w)
    lists.push_back({&contacts_[w].pairs, &wall_grids_[w], contact_kernel(walls_[w].h()), /*exclude_self=*/false});
  for (std::size_t s = 0; s < solids_.size(); ++s) {
    const WendlandC2 kernel = contact_kernel(solids_[s].h());
    solid_grids.emplace_back(box_, kernel.cutoff());
    solid_grids.back().build(solids_[s].particles.pos);
    lists.push_back({&contacts_[walls_.size() + s].pairs, &solid_grids.back(), kernel, /*exclude_self=*/false});
  }
  build_lists(f.pos, lists);
  parallel_for_each(contacts_.size(), [&](std::size_t c) {
    FluidContact& contact = contacts_[c];
    const std::size_t boundary_count = lists[c + 1].target->size();
    contact.pairs_of_boundary.build(contact.pairs, boundary_count);
    if (contact.boundary_dissipation_reaction.size() != boundary_count)
      contact.boundary_dissipation_reaction.assign(boundary_count, Vec2::Zero());
  }, /*grain=*/1, Sharing::Balanced);
  if (fluid.options.refreshes_pair_geometry()) record_positions_at_list_build();
}

void Simulation::record_positions_at_list_build() {
  fluid_->positions_at_list_build = fluid_->particles.pos;
  for (FluidContact& contact : contacts_)
    if (contact.boundary.pos != nullptr) contact.boundary_positions_at_list_build = *contact.boundary.pos;
}

namespace {

[[noreturn]] void diverged(const Simulation& sim, const std::string& body, std::size_t particle, const std::string& why) {
  throw DivergenceError(DivergenceInfo{sim.time, sim.steps.advection, body, static_cast<long long>(particle), why});
}

std::string vec_text(const Vec2& v) {
  std::ostringstream s;
  s << "(" << v.x() << ", " << v.y() << ")";
  return s.str();
}

}  // namespace

// Why fluid particle i marks a diverged run, if it does; the checks in the order they are reported.
std::optional<std::string> Simulation::fluid_particle_fault(std::size_t i) const {
  const FluidParticles& f = fluid_->particles;
  const Real limit = limits.speed_factor * fluid_->material.sound_speed();
  if (!f.pos[i].allFinite() || !f.vel[i].allFinite() || !std::isfinite(f.rho[i]))
    return "non-finite position, velocity or density";
  const Real speed = f.vel[i].norm();
  if (speed > limit)
    return "runaway speed |v| = " + std::to_string(speed) + " > " + std::to_string(limit) + " (" +
           std::to_string(limits.speed_factor) + " c_F)";
  if (!box_.contains(f.pos[i])) return "particle left the domain at " + vec_text(f.pos[i]);
  if (!(f.rho[i] > 0.0)) return "non-positive density " + std::to_string(f.rho[i]);
  return std::nullopt;
}

void Simulation::check_divergence() const {
  if (fluid_) {
    // The first faulty particle, as a serial scan would report it.
    const std::size_t n = fluid_->particles.size();
    const std::size_t i = parallel_find_first(n, [&](std::size_t k) { return fluid_particle_fault(k).has_value(); });
    if (i < n) diverged(*this, fluid_->name, i, *fluid_particle_fault(i));
  }
  for (const SolidBody& solid : solids_) {
    const SolidParticles& s = solid.particles;
    const Real limit = limits.speed_factor * solid.material.sound_speed();
    for (std::size_t a = 0; a < s.size(); ++a) {
      if (!s.pos[a].allFinite() || !s.vel[a].allFinite() || !s.F[a].allFinite())
        diverged(*this, solid.name, a, "non-finite position, velocity or deformation gradient");
      const Real J = s.F[a].determinant();
      if (!(J > 0.0)) diverged(*this, solid.name, a, "inverted element, J = det F = " + std::to_string(J));
      const Real speed = s.vel[a].norm();
      if (speed > limit)
        diverged(*this, solid.name, a, "runaway speed |v| = " + std::to_string(speed) + " > " +
                                           std::to_string(limit) + " (" + std::to_string(limits.speed_factor) + " c_S)");
      if (!box_.contains(s.pos[a])) diverged(*this, solid.name, a, "particle left the domain at " + vec_text(s.pos[a]));
    }
  }
}

std::size_t Simulation::particle_count() const {
  std::size_t n = fluid_ ? fluid_->particles.size() : 0;
  for (const WallBody& w : walls_) n += w.particles.size();
  for (const SolidBody& s : solids_) n += s.particles.size();
  return n;
}

}  // namespace mrsph
