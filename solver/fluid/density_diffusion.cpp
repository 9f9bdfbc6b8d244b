#include "fluid/density_diffusion.hpp"

#include "core/parallel.hpp"
#include "interaction/pair_sweep.hpp"

#include <cmath>

namespace mrsph {

namespace {

// <grad rho>^L_i = L_i sum_j V_j (rho_j - rho_i) grad W_ij, L_i = (sum_j V_j (r_j - r_i) (x) grad W_ij)^-1.
struct RenormalisedGradient {
  struct Sum {
    Mat2 moment = Mat2::Zero();
    Vec2 difference = Vec2::Zero();
  };
  const FluidParticles& f;
  Vec2Array& gradient;
  Real smallest_determinant;

  Sum begin(std::size_t) const { return {}; }
  void pair(Sum& s, std::size_t i, Index, const Neighbor& n) const {
    const Vec2 grad = n.dW * n.e;
    s.moment -= (f.vol[n.j] * n.r) * (n.e * grad.transpose());  // sum V_j (r_j - r_i) (x) grad W
    s.difference += (f.vol[n.j] * (f.rho[n.j] - f.rho[i])) * grad;
  }
  void finish(std::size_t i, const Sum& s) const {
    const Real det = s.moment.determinant();
    gradient[i] = std::abs(det) < smallest_determinant ? Vec2::Zero() : Vec2(s.moment.inverse() * s.difference);
  }
};

}  // namespace

void compute_renormalised_density_gradient(FluidBody& fluid, const NeighborList& inner) {
  if (fluid.options.delta_sph == 0.0) return;
  const FluidParticles& f = fluid.particles;
  fluid.density_gradient.resize(f.size());
  // A full support gives L^-1 = M1 I (0.974 at h = 1.3 dp); below a tenth of that squared, the
  // particle has lost most of its support and the inverse would amplify noise.
  constexpr Real kSmallestDeterminant = 0.01;
  sweep_pairs(inner, RenormalisedGradient{f, fluid.density_gradient, kSmallestDeterminant});
}

}  // namespace mrsph
