// Fills a region with particles.
//   lattice: a square lattice of spacing dp, points origin + R(angle) (i + 1/2, j + 1/2) dp,
//            origin = the region's lower bounding corner unless given, angle 0 unless given (a
//            rotated lattice follows an inclined body: straight rows, no staircase);
//   rings:   concentric rings about a centre with radial spacing R / round(R / dp) and about dp
//            along each ring: a smooth circular surface (used for the cylinder). A ring cut by the
//            region's boundary (the cylinder minus the beam's root) is spaced evenly along each
//            arc left, its end particles half a spacing along the ring from the cut;
// Otherwise a point is kept if it lies at least `clearance` * dp inside the region's boundary, so a lattice
// aligned with a flat boundary keeps its first row at dp/2 from it, and particles of one body
// never crowd the surface of a shape cut out for another body.
#pragma once

#include "geometry/shapes.hpp"

#include <optional>

namespace mrsph {

enum class FillPattern { Lattice, Rings };

struct FillSpec {
  FillPattern pattern = FillPattern::Lattice;
  std::optional<Vec2> lattice_origin;
  Real lattice_angle = 0.0;  // radians
  Vec2 ring_center = Vec2::Zero();
  Real ring_radius = 0.0;
  Real clearance = 0.5;  // in units of dp
};

struct GeneratedParticles {
  Vec2Array pos;
  RealArray vol;
};

GeneratedParticles generate_particles(const Shape& region, Real dp, const FillSpec& fill);

// How many lattice points the region's bounding box holds: an upper bound used to refuse a scene
// that would need more particles than allowed, before anything is allocated.
double lattice_capacity(const Shape& region, Real dp);

}  // namespace mrsph
