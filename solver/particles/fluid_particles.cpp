#include "particles/fluid_particles.hpp"

namespace mrsph {

namespace {
template <class Array>
void permute_array(Array& a, const std::vector<Index>& order) {
  Array out(a.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[k] = a[order[k]];
  a.swap(out);
}
}  // namespace

void FluidParticles::permute(const std::vector<Index>& order) {
  permute_array(pos, order); permute_array(vel, order); permute_array(rho, order); permute_array(p, order);
  permute_array(mass, order); permute_array(vol, order); permute_array(drho_dt, order);
  permute_array(pressure_force, order); permute_array(dissipation_force, order); permute_array(force_prior, order);
}

}  // namespace mrsph
