#include "boundary/initial_velocity.hpp"

#include <cmath>

namespace mrsph {

namespace {

Vec2 evaluate(const UniformVelocity& f, const Vec2&) { return f.value; }

Vec2 evaluate(const WomersleyVelocity& f, const Vec2& p) { return Vec2(f.profile.velocity(p.y(), f.time), 0.0); }

Vec2 evaluate(const CantileverModeVelocity& f, const Vec2& p) {
  const Real x = p.x() - f.clamp_x;
  if (x <= 0.0) return Vec2::Zero();
  const Real kL = f.kL, k = kL / f.length;
  const Real M = std::sin(kL) + std::sinh(kL);
  const Real N = std::cos(kL) + std::cosh(kL);
  const Real Q = 2.0 * (std::cos(kL) * std::sinh(kL) - std::sin(kL) * std::cosh(kL));
  const Real shape = (M * (std::cos(k * x) - std::cosh(k * x)) - N * (std::sin(k * x) - std::sinh(k * x))) / Q;
  return Vec2(0.0, f.amplitude * shape);
}

Vec2 evaluate(const VelocityField& f, const Vec2& p) { return f.at(p); }

}  // namespace

Vec2 initial_velocity_at(const InitialVelocity& field, const Vec2& p) {
  return std::visit([&](const auto& f) { return evaluate(f, p); }, field);
}

}  // namespace mrsph
