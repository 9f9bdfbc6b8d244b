// Plane shapes for particle generation and region tests, combined by union, intersection and
// difference. signed_distance is negative inside; for combinations it is the usual min/max bound,
// exact near a single boundary (which is all the generator's clearance test needs).
#pragma once

#include "core/types.hpp"

#include <memory>
#include <vector>

namespace mrsph {

struct BoundingBox {
  Vec2 lower, upper;
};

class Shape {
 public:
  virtual ~Shape() = default;
  virtual Real signed_distance(const Vec2& p) const = 0;
  virtual BoundingBox bounds() const = 0;
  bool contains(const Vec2& p) const { return signed_distance(p) < 0.0; }
};

using ShapePtr = std::shared_ptr<const Shape>;

class Rectangle final : public Shape {
 public:
  Rectangle(Vec2 lower, Vec2 upper);
  Real signed_distance(const Vec2& p) const override;
  BoundingBox bounds() const override { return {lower_, upper_}; }

 private:
  Vec2 lower_, upper_;
};

class Circle final : public Shape {
 public:
  Circle(Vec2 center, Real radius);
  Real signed_distance(const Vec2& p) const override { return (p - center_).norm() - radius_; }
  BoundingBox bounds() const override {
    return {center_ - Vec2::Constant(radius_), center_ + Vec2::Constant(radius_)};
  }
  const Vec2& center() const { return center_; }
  Real radius() const { return radius_; }

 private:
  Vec2 center_;
  Real radius_;
};

// A simple polygon (vertices in order, either orientation, not self-intersecting).
class Polygon final : public Shape {
 public:
  explicit Polygon(std::vector<Vec2> vertices);
  Real signed_distance(const Vec2& p) const override;
  BoundingBox bounds() const override { return box_; }

 private:
  std::vector<Vec2> vertices_;
  BoundingBox box_;
};

// The outline of the paper's fish-like body (section 4.4; CASES.md section 4): y = +/- c(s) about a
// centre line through the head tip along +x, c(s) = sum_{i=1..5} a_i s^i with s the distance from the
// TAIL tip and a_i = coefficient_i * thickness / length^i. Where the half-thickness is below
// min_half_thickness the thin ends are dropped (as the paper's code does). Built as a polygon.
Polygon fish_outline(const Vec2& head_tip, Real length, Real thickness, const std::vector<Real>& coefficients,
                     Real min_half_thickness, int points_per_side = 200);
// Its half-thickness c(s) at the distance s from the tail tip.
Real fish_half_thickness(Real s, Real length, Real thickness, const std::vector<Real>& coefficients);

class Union final : public Shape {
 public:
  explicit Union(std::vector<ShapePtr> parts);
  Real signed_distance(const Vec2& p) const override;
  BoundingBox bounds() const override;

 private:
  std::vector<ShapePtr> parts_;
};

class Intersection final : public Shape {
 public:
  explicit Intersection(std::vector<ShapePtr> parts);
  Real signed_distance(const Vec2& p) const override;
  BoundingBox bounds() const override;

 private:
  std::vector<ShapePtr> parts_;
};

class Difference final : public Shape {
 public:
  Difference(ShapePtr base, std::vector<ShapePtr> subtract);
  Real signed_distance(const Vec2& p) const override;
  BoundingBox bounds() const override { return base_->bounds(); }

 private:
  ShapePtr base_;
  std::vector<ShapePtr> subtract_;
};

}  // namespace mrsph
