#include "solid/solid_contact.hpp"

#include "interaction/pair_sweep.hpp"
#include "neighbor/cell_grid.hpp"

#include <algorithm>

namespace mrsph {

Real default_contact_stiffness(const SolidBody& a, const SolidBody& b) {
  const auto modulus = [](const SolidBody& s) {
    const Real c = s.material.sound_speed();
    return s.material.density() * c * c;
  };
  return std::min(modulus(a), modulus(b));
}

namespace {

// One side of a contact: its particles' positions and volumes, those that take no part (null: none),
// and where their forces go (null: a fixed wall, whose reaction is not applied).
struct ContactSide {
  const Vec2Array& pos;
  const RealArray& vol;
  const std::vector<std::uint8_t>* excluded = nullptr;
  Vec2Array* force = nullptr;          // null: a fixed side (a wall), or forces not wanted
  RealArray* stiffness = nullptr;      // with force: the contact's stiffness per particle, Gershgorin-weighted

  bool takes_part(std::size_t i) const { return excluded == nullptr || (*excluded)[i] == 0; }
};

ContactSide side_of(const SolidBody& s) { return {s.particles.pos, s.particles.vol0}; }
ContactSide side_of(SolidBody& s) {
  return {s.particles.pos, s.particles.vol0, nullptr, &s.external_force, &s.particles.contact_stiffness};
}
ContactSide wall_side(const SolidContact& c) { return {c.wall_pos, c.wall_vol}; }
// A solid against a wall: its clamped particles are attached to that wall (header).
ContactSide solid_side_at_wall(SolidBody& s) {
  return {s.particles.pos, s.particles.vol0, &s.particles.constrained, &s.external_force, &s.particles.contact_stiffness};
}
ContactSide solid_side_at_wall(const SolidBody& s) { return {s.particles.pos, s.particles.vol0, &s.particles.constrained}; }

void prepare(SolidContact& contact, Real support, Real default_stiffness) {
  contact.kernel = WendlandC2(0.5 * support);
  contact.skin = 0.5 * support;
  if (contact.stiffness <= 0.0) contact.stiffness = default_stiffness;
  contact.travel = std::numeric_limits<Real>::infinity();
  contact.candidates.clear();
}

void refresh(SolidContact& contact, const ContactSide& a, const ContactSide& b) {
  if (contact.travel <= contact.skin) return;
  const Real radius = contact.kernel.cutoff() + contact.skin;
  const DomainBox unbounded;  // solids are never wrapped: their positions are used as they are
  CellGrid grid(unbounded, radius);
  grid.build(b.pos);
  // Sorted, so the sums below run in one order however the list was built: results do not depend on
  // when it was rebuilt (pairs beyond the support add exactly zero).
  list_pairs_within(a.pos, grid, radius, [&](std::size_t i) { return a.takes_part(i); },
                    [&](std::size_t j) { return b.takes_part(j); }, contact.candidates);
  contact.travel = 0.0;
}

// phi of every particle of both sides that has a candidate pair (others stay 0).
void contact_overlaps(const SolidContact& contact, const ContactSide& a, const ContactSide& b, RealArray& phi_a,
                      RealArray& phi_b) {
  phi_a.assign(a.pos.size(), 0.0);
  phi_b.assign(b.pos.size(), 0.0);
  for_each_listed_pair(contact.candidates, [&](Index i, Index j) {
    const Real w = contact.kernel.W((a.pos[i] - b.pos[j]).norm());
    phi_a[i] += b.vol[j] * w;
    phi_b[j] += a.vol[i] * w;
  });
}

// The pair's stiffness, the largest eigenvalue of the Jacobian of its force (header): along the line of
// centres -dF/dr = V_a V_b [k_c (V_a + V_b) W'^2 + (p_a + p_b) W''] (the pair's own share of p_a and p_b
// moves with r), across it F / r.
Real pair_stiffness(const SolidContact& contact, Real vol_a, Real vol_b, Real pressure_sum, Real r, Real dW) {
  const Real along = contact.stiffness * (vol_a + vol_b) * dW * dW + pressure_sum * contact.kernel.d2W(r);
  const Real across = -pressure_sum * dW / r;
  return vol_a * vol_b * std::max(std::abs(along), std::abs(across));
}

void add_forces(const SolidContact& contact, const ContactSide& a, const ContactSide& b) {
  if (contact.candidates.empty()) return;
  RealArray phi_a, phi_b;
  contact_overlaps(contact, a, b, phi_a, phi_b);
  // Gershgorin's bound on the contact's highest frequency: a particle's row of M^-1/2 K M^-1/2 sums
  // K_ab / m_a for itself and K_ab / sqrt(m_a m_b) for a moving partner; for bodies of one spacing and
  // density, 2 K_ab / m_a against a moving body and K_ab / m_a against a fixed one. Stored times m_a.
  const Real weight_a = b.force ? 2.0 : 1.0, weight_b = a.force ? 2.0 : 1.0;
  for_each_listed_pair(contact.candidates, [&](Index i, Index j) {
    const Vec2 d = a.pos[i] - b.pos[j];
    const Real r = d.norm();
    if (r >= contact.kernel.cutoff() || r == 0.0) return;
    const Real pressure_sum = contact.stiffness * (phi_a[i] + phi_b[j]);
    const Real dW = contact.kernel.dW(r);
    const Vec2 f = -(a.vol[i] * b.vol[j] * pressure_sum * dW / r) * d;
    const Real k = pair_stiffness(contact, a.vol[i], b.vol[j], pressure_sum, r, dW);
    if (a.force) {
      (*a.force)[i] += f;
      (*a.stiffness)[i] += weight_a * k;
    }
    if (b.force) {
      (*b.force)[j] -= f;
      (*b.stiffness)[j] += weight_b * k;
    }
  });
}

Real largest_overlap(const SolidContact& contact, const ContactSide& a, const ContactSide& b) {
  RealArray phi_a, phi_b;
  contact_overlaps(contact, a, b, phi_a, phi_b);
  Real largest = 0.0;
  for (Real p : phi_a) largest = std::max(largest, p);
  for (Real p : phi_b) largest = std::max(largest, p);
  return largest;
}

}  // namespace

void prepare_solid_contact(SolidContact& contact, const SolidBody& a, const SolidBody& b) {
  prepare(contact, std::max(a.dp, b.dp), default_contact_stiffness(a, b));
}

void refresh_contact_candidates(SolidContact& contact, const SolidBody& a, const SolidBody& b) {
  refresh(contact, side_of(a), side_of(b));
}

void add_contact_forces(const SolidContact& contact, SolidBody& a, SolidBody& b) {
  add_forces(contact, side_of(a), side_of(b));
}

Real largest_contact_overlap(const SolidContact& contact, const SolidBody& a, const SolidBody& b) {
  return largest_overlap(contact, side_of(a), side_of(b));
}

void prepare_wall_contact(SolidContact& contact, const SolidBody& solid, const WallParticles& wall, Real wall_dp) {
  prepare(contact, std::max(solid.dp, wall_dp), default_contact_stiffness(solid, solid));
  contact.wall_pos = wall.pos;
  contact.wall_vol = wall.vol;
}

void refresh_contact_candidates(SolidContact& contact, const SolidBody& solid) {
  refresh(contact, solid_side_at_wall(solid), wall_side(contact));
}

void add_contact_forces(const SolidContact& contact, SolidBody& solid) {
  add_forces(contact, solid_side_at_wall(solid), wall_side(contact));
}

Real largest_contact_overlap(const SolidContact& contact, const SolidBody& solid) {
  return largest_overlap(contact, solid_side_at_wall(solid), wall_side(contact));
}

void apply_contact(SolidContact& contact, std::span<SolidBody> solids) {
  SolidBody& a = solids[contact.first];
  if (contact.second_is_wall) {
    refresh_contact_candidates(contact, a);
    add_contact_forces(contact, a);
    return;
  }
  SolidBody& b = solids[contact.second];
  refresh_contact_candidates(contact, a, b);
  add_contact_forces(contact, a, b);
}

}  // namespace mrsph
