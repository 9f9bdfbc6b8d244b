#include "geometry/particle_generator.hpp"

#include <cmath>

namespace mrsph {

namespace {

bool keep(const Shape& region, const Vec2& p, Real margin) {
  // The tolerance keeps points that sit exactly at the clearance from a lattice-aligned boundary.
  return region.signed_distance(p) <= -margin * (1.0 - 1e-9);
}

GeneratedParticles fill_lattice(const Shape& region, Real dp, const FillSpec& fill) {
  const BoundingBox box = region.bounds();
  const Vec2 origin = fill.lattice_origin.value_or(box.lower);
  const Real c = std::cos(fill.lattice_angle), s = std::sin(fill.lattice_angle);
  // The region's bounding box in lattice coordinates bounds the indices to visit.
  Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
  for (const Vec2& corner : {box.lower, box.upper, Vec2(box.lower.x(), box.upper.y()), Vec2(box.upper.x(), box.lower.y())}) {
    const Vec2 d = corner - origin;
    const Vec2 local(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
    lo = lo.cwiseMin(local);
    hi = hi.cwiseMax(local);
  }
  const int i0 = static_cast<int>(std::floor(lo.x() / dp)) - 1, i1 = static_cast<int>(std::ceil(hi.x() / dp)) + 1;
  const int j0 = static_cast<int>(std::floor(lo.y() / dp)) - 1, j1 = static_cast<int>(std::ceil(hi.y() / dp)) + 1;
  GeneratedParticles out;
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const Vec2 local = Vec2(i + 0.5, j + 0.5) * dp;
      const Vec2 p = origin + Vec2(c * local.x() - s * local.y(), s * local.x() + c * local.y());
      if (!keep(region, p, fill.clearance * dp)) continue;
      out.pos.push_back(p);
      out.vol.push_back(dp * dp);
    }
  return out;
}

GeneratedParticles fill_rings(const Shape& region, Real dp, const FillSpec& fill) {
  const Real R = fill.ring_radius;
  const int rings = std::max(1, static_cast<int>(std::lround(R / dp)));
  const Real dr = R / rings;
  GeneratedParticles out;
  for (int k = rings - 1; k >= 0; --k) {
    const Real r = (k + 0.5) * dr;
    const int n = std::max(1, static_cast<int>(std::lround(2.0 * kPi * r / dp)));
    const Real volume = 2.0 * kPi * r * dr / n;
    const Real offset = (k % 2) * kPi / n;  // stagger successive rings
    for (int m = 0; m < n; ++m) {
      const Real angle = offset + 2.0 * kPi * m / n;
      const Vec2 p = fill.ring_center + r * Vec2(std::cos(angle), std::sin(angle));
      if (!keep(region, p, fill.clearance * dr)) continue;
      out.pos.push_back(p);
      out.vol.push_back(volume);
    }
  }
  return out;
}

}  // namespace

GeneratedParticles generate_particles(const Shape& region, Real dp, const FillSpec& fill) {
  return fill.pattern == FillPattern::Lattice ? fill_lattice(region, dp, fill) : fill_rings(region, dp, fill);
}

double lattice_capacity(const Shape& region, Real dp) {
  const BoundingBox box = region.bounds();
  return (std::ceil((box.upper.x() - box.lower.x()) / dp) + 3.0) * (std::ceil((box.upper.y() - box.lower.y()) / dp) + 3.0);
}

}  // namespace mrsph
