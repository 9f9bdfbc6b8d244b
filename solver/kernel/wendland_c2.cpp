#include "kernel/wendland_c2.hpp"

#include <cmath>
#include <stdexcept>

namespace mrsph {

WendlandC2::WendlandC2(Real h)
    : h_(h), inv_h_(1.0 / h), factor_W_(7.0 / (4.0 * kPi * h * h)), factor_dW_(-35.0 / (4.0 * kPi * h * h * h)) {
  if (!(h > 0.0) || !std::isfinite(h)) throw std::invalid_argument("WendlandC2: smoothing length must be positive");
}

}  // namespace mrsph
