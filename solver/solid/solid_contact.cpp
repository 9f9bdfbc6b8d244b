#include "solid/solid_contact.hpp"

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

void prepare_solid_contact(SolidContact& contact, const SolidBody& a, const SolidBody& b) {
  const Real support = std::max(a.dp, b.dp);
  contact.kernel = WendlandC2(0.5 * support);
  contact.skin = 0.5 * support;
  if (contact.stiffness <= 0.0) contact.stiffness = default_contact_stiffness(a, b);
  contact.travel = std::numeric_limits<Real>::infinity();
  contact.candidates.clear();
}

void refresh_contact_candidates(SolidContact& contact, const SolidBody& a, const SolidBody& b) {
  if (contact.travel <= contact.skin) return;
  const Real radius = contact.kernel.cutoff() + contact.skin;
  const DomainBox unbounded;  // solids are never wrapped: their positions are used as they are
  CellGrid grid(unbounded, radius);
  grid.build(b.particles.pos);
  contact.candidates.clear();
  const Vec2Array& pa = a.particles.pos;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    if (!grid.within_reach(pa[i])) continue;
    grid.for_each_run_near(pa[i], [&](Index begin, Index end, const Vec2&) {
      for (Index k = begin; k < end; ++k)
        if ((pa[i] - grid.sorted_position(k)).squaredNorm() < radius * radius)
          contact.candidates.emplace_back(static_cast<Index>(i), grid.sorted_index(k));
    });
  }
  // Sorted, so the sums below run in one order however the list was built: results do not depend on
  // when it was rebuilt (pairs beyond the support add exactly zero).
  std::sort(contact.candidates.begin(), contact.candidates.end());
  contact.travel = 0.0;
}

namespace {
// phi of every particle of both bodies that has a candidate pair (others stay 0).
void contact_overlaps(const SolidContact& contact, const SolidBody& a, const SolidBody& b, RealArray& phi_a,
                      RealArray& phi_b) {
  phi_a.assign(a.particles.size(), 0.0);
  phi_b.assign(b.particles.size(), 0.0);
  for (const auto& [i, j] : contact.candidates) {
    const Real w = contact.kernel.W((a.particles.pos[i] - b.particles.pos[j]).norm());
    phi_a[i] += b.particles.vol0[j] * w;
    phi_b[j] += a.particles.vol0[i] * w;
  }
}
}  // namespace

void add_contact_forces(const SolidContact& contact, SolidBody& a, SolidBody& b) {
  if (contact.candidates.empty()) return;
  RealArray phi_a, phi_b;
  contact_overlaps(contact, a, b, phi_a, phi_b);
  for (const auto& [i, j] : contact.candidates) {
    const Vec2 d = a.particles.pos[i] - b.particles.pos[j];
    const Real r = d.norm();
    if (r >= contact.kernel.cutoff() || r == 0.0) continue;
    const Real pressure_sum = contact.stiffness * (phi_a[i] + phi_b[j]);
    const Vec2 f = -(a.particles.vol0[i] * b.particles.vol0[j] * pressure_sum * contact.kernel.dW(r) / r) * d;
    a.external_force[i] += f;
    b.external_force[j] -= f;
  }
}

Real largest_contact_overlap(const SolidContact& contact, const SolidBody& a, const SolidBody& b) {
  RealArray phi_a, phi_b;
  contact_overlaps(contact, a, b, phi_a, phi_b);
  Real largest = 0.0;
  for (Real p : phi_a) largest = std::max(largest, p);
  for (Real p : phi_b) largest = std::max(largest, p);
  return largest;
}

}  // namespace mrsph
