// An elastic solid body: particles, resolution, material, and its neighbour list in the
// reference configuration (built once; total Lagrangian).
#pragma once

#include "kernel/wendland_c2.hpp"
#include "neighbor/neighbor_list.hpp"
#include "particles/boundary_view.hpp"
#include "particles/solid_particles.hpp"
#include "solid/elastic_material.hpp"

#include <string>

namespace mrsph {

struct SolidOptions {
  Real cfl = 0.6;  // paper Eq. 34
};

struct SolidBody {
  std::string name;
  Real dp;
  WendlandC2 kernel;
  ElasticMaterial material;
  SolidOptions options;
  SolidParticles particles;
  NeighborList inner;  // reference configuration

  SolidBody(std::string body_name, Real spacing, Real h_over_dp, ElasticMaterial elastic)
      : name(std::move(body_name)), dp(spacing), kernel(h_over_dp * spacing), material(std::move(elastic)) {}
  Real h() const { return kernel.h(); }
  BoundaryView boundary_view() const {
    return BoundaryView{&particles.vol0, &particles.normal, &particles.vel_ave, &particles.acc_ave};
  }
};

}  // namespace mrsph
