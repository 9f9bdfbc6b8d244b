#include "geometry/particle_generator.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

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

// The angular intervals [begin, end] (begin < end, possibly past 2 pi) where the ring of radius r
// lies inside the region; empty when the whole ring does. Crossings are sampled at a fraction of a
// spacing and refined by bisection.
struct Arc {
  Real begin, end;
};

std::vector<Arc> arcs_inside(const Shape& region, const Vec2& center, Real r, Real dp) {
  const auto inside = [&](Real angle) { return region.contains(center + r * Vec2(std::cos(angle), std::sin(angle))); };
  const int samples = std::max(64, 16 * static_cast<int>(std::ceil(2.0 * kPi * r / dp)));
  const Real step = 2.0 * kPi / samples;
  int start = 0;  // a sample outside the region, so that no arc wraps past the start
  while (start < samples && inside(start * step)) ++start;
  if (start == samples) return {};
  const auto crossing = [&](Real a, Real b) {  // inside(a) != inside(b)
    const bool at_a = inside(a);
    for (int i = 0; i < 60; ++i) {
      const Real mid = 0.5 * (a + b);
      (inside(mid) == at_a ? a : b) = mid;
    }
    return 0.5 * (a + b);
  };
  std::vector<Arc> arcs;
  bool was_inside = false;
  for (int m = start + 1; m <= start + samples; ++m) {
    const bool now_inside = inside(m * step);
    if (now_inside == was_inside) continue;
    const Real angle = crossing((m - 1) * step, m * step);
    if (now_inside)
      arcs.push_back({angle, angle});
    else
      arcs.back().end = angle;
    was_inside = now_inside;
  }
  return arcs;
}

GeneratedParticles fill_rings(const Shape& region, Real dp, const FillSpec& fill) {
  const Real R = fill.ring_radius;
  const int rings = std::max(1, static_cast<int>(std::lround(R / dp)));
  const Real dr = R / rings;
  GeneratedParticles out;
  const auto add = [&](const Vec2& p, Real volume) {
    out.pos.push_back(p);
    out.vol.push_back(volume);
  };
  for (int k = rings - 1; k >= 0; --k) {
    const Real r = (k + 0.5) * dr;
    const std::vector<Arc> arcs = arcs_inside(region, fill.ring_center, r, dp);
    if (arcs.empty()) {  // a whole ring, staggered against its neighbours
      const int n = std::max(1, static_cast<int>(std::lround(2.0 * kPi * r / dp)));
      const Real offset = (k % 2) * kPi / n;
      for (int m = 0; m < n; ++m) {
        const Real angle = offset + 2.0 * kPi * m / n;
        const Vec2 p = fill.ring_center + r * Vec2(std::cos(angle), std::sin(angle));
        if (keep(region, p, fill.clearance * dr)) add(p, 2.0 * kPi * r * dr / n);
      }
      continue;
    }
    // A ring cut by another body's shape: each arc gets its own even spacing, its end particles half
    // a spacing from the cut, so that no gap of more than a spacing opens beside the other body.
    for (const Arc& arc : arcs) {
      const Real length = r * (arc.end - arc.begin);
      const int n = static_cast<int>(std::lround(length / dp));
      for (int m = 0; m < n; ++m) {
        const Real angle = arc.begin + (arc.end - arc.begin) * (m + 0.5) / n;
        add(fill.ring_center + r * Vec2(std::cos(angle), std::sin(angle)), length * dr / n);
      }
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
