// A rigid, fixed wall body made of dummy particles (Adami et al. 2012).
#pragma once

#include "kernel/wendland_c2.hpp"
#include "particles/boundary_view.hpp"
#include "particles/wall_particles.hpp"

#include <string>

namespace mrsph {

struct WallBody {
  std::string name;
  Real dp;
  WendlandC2 kernel;
  WallParticles particles;

  WallBody(std::string body_name, Real spacing, Real h_over_dp)
      : name(std::move(body_name)), dp(spacing), kernel(h_over_dp * spacing) {}
  Real h() const { return kernel.h(); }
  BoundaryView boundary_view() const {
    return BoundaryView{&particles.vol, &particles.normal, &particles.vel_ave, &particles.acc_ave, /*pos=*/nullptr,  // never moves
                        &particles.depth};
  }
};

}  // namespace mrsph
