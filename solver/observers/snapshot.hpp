// Particle snapshots of every body, with the fields a ParaView user looks at:
//   fluid: velocity, pressure, density, vorticity  omega_i = sum_j V_j (v_j - v_i) x grad_i W_ij
//   solid: velocity, displacement, density, J, von Mises stress (plane strain, Cauchy stress)
//   wall:  normal
#pragma once

#include "io/vtp_writer.hpp"
#include "simulation/simulation.hpp"

namespace mrsph {

PointCloud fluid_snapshot(const Simulation& sim);
PointCloud wall_snapshot(const WallBody& wall);
PointCloud solid_snapshot(const SolidBody& solid);

RealArray fluid_vorticity(const Simulation& sim);
Real von_mises_stress(const ElasticMaterial& material, const Mat2& F);

}  // namespace mrsph
