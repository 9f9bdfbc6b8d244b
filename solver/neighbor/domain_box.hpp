// The simulation box: which axes are periodic and over what interval. Non-periodic axes are
// unbounded for the neighbour search (the bounds are still used to detect particles that leave
// the domain).
#pragma once

#include "core/types.hpp"

#include <array>
#include <cmath>

namespace mrsph {

struct DomainBox {
  Vec2 lower = Vec2::Zero();
  Vec2 upper = Vec2::Ones();
  std::array<bool, 2> periodic{false, false};

  Real length(int axis) const { return upper[axis] - lower[axis]; }

  // The image of p inside [lower, upper) along periodic axes; other axes unchanged.
  Vec2 wrap(Vec2 p) const {
    for (int a = 0; a < 2; ++a) {
      if (!periodic[a]) continue;
      const Real L = length(a);
      Real x = p[a] - lower[a];
      if (!(x >= 0.0 && x < L)) {  // inside, floor(x / L) = 0 and x is kept: the call is skipped
        x -= L * std::floor(x / L);
        if (x >= L) x -= L;  // guards against x/L rounding to exactly 1
      }
      p[a] = lower[a] + x;
    }
    return p;
  }

  // Minimum-image difference a - b along periodic axes.
  Vec2 difference(const Vec2& a, const Vec2& b) const {
    Vec2 d = a - b;
    for (int k = 0; k < 2; ++k) {
      if (!periodic[k]) continue;
      const Real L = length(k);
      d[k] -= L * std::round(d[k] / L);
    }
    return d;
  }

  bool contains(const Vec2& p) const {
    for (int a = 0; a < 2; ++a)
      if (!periodic[a] && (p[a] < lower[a] || p[a] > upper[a])) return false;
    return true;
  }
};

}  // namespace mrsph
