#include "particles/fluid_particles.hpp"

#include <type_traits>

namespace mrsph {

namespace {

template <class T>
T zero_value() {
  if constexpr (std::is_arithmetic_v<T>) return T(0);
  else return T::Zero();
}

}  // namespace

void FluidParticles::resize(std::size_t n) {
  for_each_field(*this, [n](auto& a, const char*) {
    a.resize(n, zero_value<typename std::decay_t<decltype(a)>::value_type>());
  });
}

void FluidParticles::permute(const std::vector<Index>& order) {
  for_each_field(*this, [&](auto& a, const char*) {
    std::decay_t<decltype(a)> out(a.size());
    for (std::size_t k = 0; k < order.size(); ++k) out[k] = a[order[k]];
    a.swap(out);
  });
}

void FluidParticles::append_copy_of(std::size_t i) {
  for_each_field(*this, [i](auto& a, const char*) {
    const auto value = a[i];  // a copy: push_back may reallocate
    a.push_back(value);
  });
}

void FluidParticles::erase(const std::vector<bool>& remove) {
  for_each_field(*this, [&](auto& a, const char*) {
    std::size_t kept = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
      if (!remove[k]) a[kept++] = a[k];
    a.resize(kept);
  });
}

}  // namespace mrsph
