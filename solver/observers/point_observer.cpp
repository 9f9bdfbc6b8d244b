#include "observers/point_observer.hpp"

#include "fsi/fluid_solid_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace mrsph {

PointObserver::PointObserver(ObserverSpec spec, const Simulation& sim) : spec_(std::move(spec)) {
  if (spec_.bodies.empty()) throw std::invalid_argument("observer '" + spec_.name + "' names no body");
  const std::string& body = spec_.bodies.front();
  if (spec_.quantity == ObservedQuantity::Force) {
    observe_forces(sim);
  } else if (spec_.quantity == ObservedQuantity::Gap) {
    observe_gap(sim);
  } else if (sim.has_fluid() && sim.fluid().name == body) {
    observe_fluid();
  } else if (const std::optional<std::size_t> s = sim.solid_index(body)) {
    solid_index_ = *s;
    observe_solid(sim.solids()[*s]);
  } else {
    throw std::invalid_argument("observer '" + spec_.name + "': no fluid or solid body named '" + body + "'");
  }
}

void PointObserver::observe_forces(const Simulation& sim) {
  target_ = Target::Boundaries;
  if (!sim.has_fluid()) throw std::invalid_argument("observer '" + spec_.name + "': force needs a fluid");
  for (const std::string& body : spec_.bodies) {
    std::size_t k = 0;
    for (; k < sim.fluid_contacts().size(); ++k)
      if (sim.fluid_contacts()[k].boundary_name == body) break;
    if (k == sim.fluid_contacts().size())
      throw std::invalid_argument("observer '" + spec_.name + "': no wall or solid body named '" + body + "'");
    contact_indices_.push_back(k);
  }
}

void PointObserver::observe_gap(const Simulation& sim) {
  target_ = Target::SolidPair;
  if (spec_.bodies.size() != 2) throw std::invalid_argument("observer '" + spec_.name + "': a gap is between two solid bodies");
  const auto solid_named = [&](const std::string& body) {
    if (const auto index = sim.solid_index(body)) return *index;
    throw std::invalid_argument("observer '" + spec_.name + "': no solid body named '" + body + "'");
  };
  solid_index_ = solid_named(spec_.bodies[0]);
  other_solid_index_ = solid_named(spec_.bodies[1]);
}

void PointObserver::observe_fluid() {
  target_ = Target::Fluid;
  if (spec_.quantity != ObservedQuantity::Velocity && spec_.quantity != ObservedQuantity::Pressure &&
      spec_.quantity != ObservedQuantity::Front)
    throw std::invalid_argument("observer '" + spec_.name + "': a fluid body is observed as velocity, pressure or front");
  if (spec_.quantity == ObservedQuantity::Front) {
    if (!(spec_.direction.norm() > 0.0)) throw std::invalid_argument("observer '" + spec_.name + "': zero front direction");
    spec_.direction.normalize();
  }
}

// The solid's particle nearest the point, or its particles within reach weighted by W V0 (normalised).
void PointObserver::observe_solid(const SolidBody& solid) {
  target_ = Target::Solid;
  if (spec_.quantity == ObservedQuantity::Pressure || spec_.quantity == ObservedQuantity::Front)
    throw std::invalid_argument("observer '" + spec_.name + "': a solid is observed as position, displacement or velocity");
  const SolidParticles& p = solid.particles;
  if (spec_.nearest_particle) {
    Real best = std::numeric_limits<Real>::infinity();
    Index best_index = 0;
    for (std::size_t a = 0; a < p.size(); ++a) {
      const Real d = (p.pos0[a] - spec_.point).squaredNorm();
      if (d < best) { best = d; best_index = static_cast<Index>(a); }
    }
    particles_ = {best_index};
    weights_ = {1.0};
    return;
  }
  Real total = 0.0;
  for (std::size_t a = 0; a < p.size(); ++a) {
    const Real w = solid.kernel.W((p.pos0[a] - spec_.point).norm()) * p.vol0[a];
    if (w <= 0.0) continue;
    particles_.push_back(static_cast<Index>(a));
    weights_.push_back(w);
    total += w;
  }
  if (particles_.empty())
    throw std::invalid_argument("observer '" + spec_.name + "': no particle of '" + spec_.bodies.front() + "' within reach of the point");
  for (Real& w : weights_) w /= total;
}

std::vector<std::string> PointObserver::columns() const {
  switch (spec_.quantity) {
    case ObservedQuantity::Position: return {"x", "y"};
    case ObservedQuantity::Displacement: return {"dx", "dy"};
    case ObservedQuantity::Velocity: return {"u", "v"};
    case ObservedQuantity::Pressure: return {"p"};
    case ObservedQuantity::Force: return {"fx", "fy", "fx_viscous", "fy_viscous"};
    case ObservedQuantity::Front: return {"front"};
    case ObservedQuantity::Gap: return {"gap"};
  }
  return {};
}

std::vector<Real> PointObserver::sample(const Simulation& sim) const {
  if (target_ == Target::Boundaries) {
    Vec2 total = Vec2::Zero(), viscous = Vec2::Zero();
    for (std::size_t k : contact_indices_) {
      total += mean_force_on_boundary(sim.fluid_contacts()[k]);
      viscous += mean_viscous_force_on_boundary(sim.fluid_contacts()[k]);
    }
    return {total.x(), total.y(), viscous.x(), viscous.y()};
  }
  if (target_ == Target::SolidPair) {
    const Vec2Array& a = sim.solids()[solid_index_].particles.pos;
    const Vec2Array& b = sim.solids()[other_solid_index_].particles.pos;
    Real closest = std::numeric_limits<Real>::infinity();
    for (const Vec2& p : a)
      for (const Vec2& q : b) closest = std::min(closest, (p - q).squaredNorm());
    return {std::sqrt(closest)};
  }
  if (target_ == Target::Solid) {
    const SolidParticles& p = sim.solids()[solid_index_].particles;
    Vec2 value = Vec2::Zero();
    for (std::size_t k = 0; k < particles_.size(); ++k) {
      const Index a = particles_[k];
      const Vec2 q = spec_.quantity == ObservedQuantity::Position       ? p.pos[a]
                     : spec_.quantity == ObservedQuantity::Displacement ? Vec2(p.pos[a] - p.pos0[a])
                                                                        : p.vel[a];
      value += weights_[k] * q;
    }
    return {value.x(), value.y()};
  }
  const FluidBody& fluid = sim.fluid();
  const FluidParticles& f = fluid.particles;
  if (spec_.quantity == ObservedQuantity::Front) {
    Real front = -std::numeric_limits<Real>::infinity();
    for (const Vec2& p : f.pos) front = std::max(front, p.dot(spec_.direction));
    return {front};
  }
  Real weight = 0.0, pressure = 0.0;
  Vec2 velocity = Vec2::Zero();
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Real w = fluid.kernel.W(sim.box().difference(f.pos[i], spec_.point).norm()) * f.vol[i];
    if (w <= 0.0) continue;
    weight += w;
    velocity += w * f.vel[i];
    pressure += w * f.p[i];
  }
  if (weight > 0.0) { velocity /= weight; pressure /= weight; }
  if (spec_.quantity == ObservedQuantity::Pressure) return {pressure};
  return {velocity.x(), velocity.y()};
}

}  // namespace mrsph
