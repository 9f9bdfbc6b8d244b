#include "geometry/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrsph {

Rectangle::Rectangle(Vec2 lower, Vec2 upper) : lower_(lower), upper_(upper) {
  if (!(upper.x() > lower.x() && upper.y() > lower.y()))
    throw std::invalid_argument("rectangle: upper corner must lie above and to the right of the lower corner");
}

Real Rectangle::signed_distance(const Vec2& p) const {
  const Vec2 center = 0.5 * (lower_ + upper_);
  const Vec2 half = 0.5 * (upper_ - lower_);
  const Vec2 q = (p - center).cwiseAbs() - half;
  const Real outside = q.cwiseMax(0.0).norm();
  const Real inside = std::min(std::max(q.x(), q.y()), Real(0));
  return outside + inside;
}

Circle::Circle(Vec2 center, Real radius) : center_(center), radius_(radius) {
  if (!(radius > 0.0)) throw std::invalid_argument("circle: radius must be positive");
}

Polygon::Polygon(std::vector<Vec2> vertices) : vertices_(std::move(vertices)) {
  if (vertices_.size() < 3) throw std::invalid_argument("polygon: needs at least 3 vertices");
  box_.lower = box_.upper = vertices_[0];
  for (const Vec2& v : vertices_) {
    box_.lower = box_.lower.cwiseMin(v);
    box_.upper = box_.upper.cwiseMax(v);
  }
}

Real Polygon::signed_distance(const Vec2& p) const {
  Real distance2 = std::numeric_limits<Real>::infinity();
  bool inside = false;
  const std::size_t n = vertices_.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = vertices_[i];
    const Vec2& b = vertices_[j];
    const Vec2 e = b - a, w = p - a;
    const Real t = std::clamp(w.dot(e) / e.squaredNorm(), Real(0), Real(1));
    distance2 = std::min(distance2, (w - t * e).squaredNorm());
    // Even-odd crossing test along +x.
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) * e.x() / e.y()) inside = !inside;
  }
  const Real d = std::sqrt(distance2);
  return inside ? -d : d;
}

Real fish_half_thickness(Real s, Real length, Real thickness, const std::vector<Real>& coefficients) {
  Real c = 0.0, power = 1.0;
  for (std::size_t i = 0; i < coefficients.size(); ++i) {
    power *= s / length;
    c += coefficients[i] * thickness * power;  // a_i s^i = coefficient_i (thickness / length^i) s^i
  }
  return c;
}

Polygon fish_outline(const Vec2& head_tip, Real length, Real thickness, const std::vector<Real>& coefficients,
                     Real min_half_thickness, int points_per_side) {
  auto half = [&](Real s) { return fish_half_thickness(s, length, thickness, coefficients); };
  std::vector<Vec2> upper, lower;
  for (int k = 0; k <= points_per_side; ++k) {
    const Real s = length * k / points_per_side;  // from the tail tip
    const Real c = half(s);
    if (c < min_half_thickness) continue;
    const Real x = head_tip.x() + length - s;
    upper.emplace_back(x, head_tip.y() + c);
    lower.emplace_back(x, head_tip.y() - c);
  }
  if (upper.size() < 2) throw std::invalid_argument("fish outline: no part of the body is thicker than the minimum");
  std::vector<Vec2> vertices(upper.begin(), upper.end());
  vertices.insert(vertices.end(), lower.rbegin(), lower.rend());
  return Polygon(std::move(vertices));
}

Union::Union(std::vector<ShapePtr> parts) : parts_(std::move(parts)) {
  if (parts_.empty()) throw std::invalid_argument("union: needs at least one shape");
}
Real Union::signed_distance(const Vec2& p) const {
  Real d = std::numeric_limits<Real>::infinity();
  for (const auto& s : parts_) d = std::min(d, s->signed_distance(p));
  return d;
}
BoundingBox Union::bounds() const {
  BoundingBox b = parts_[0]->bounds();
  for (const auto& s : parts_) {
    b.lower = b.lower.cwiseMin(s->bounds().lower);
    b.upper = b.upper.cwiseMax(s->bounds().upper);
  }
  return b;
}

Intersection::Intersection(std::vector<ShapePtr> parts) : parts_(std::move(parts)) {
  if (parts_.empty()) throw std::invalid_argument("intersection: needs at least one shape");
}
Real Intersection::signed_distance(const Vec2& p) const {
  Real d = -std::numeric_limits<Real>::infinity();
  for (const auto& s : parts_) d = std::max(d, s->signed_distance(p));
  return d;
}
BoundingBox Intersection::bounds() const {
  BoundingBox b = parts_[0]->bounds();
  for (const auto& s : parts_) {
    b.lower = b.lower.cwiseMax(s->bounds().lower);
    b.upper = b.upper.cwiseMin(s->bounds().upper);
  }
  return b;
}

Difference::Difference(ShapePtr base, std::vector<ShapePtr> subtract)
    : base_(std::move(base)), subtract_(std::move(subtract)) {}
Real Difference::signed_distance(const Vec2& p) const {
  Real d = base_->signed_distance(p);
  for (const auto& s : subtract_) d = std::max(d, -s->signed_distance(p));
  return d;
}

}  // namespace mrsph
