#include "fluid/reference_pressure.hpp"

#include "fluid/fluid_body.hpp"

namespace mrsph {

namespace {

// The mass-weighted mean of eos(rho) (equal masses: the plain mean).
Real mean_pressure(const FluidBody& fluid) {
  const FluidParticles& f = fluid.particles;
  Real mass = 0.0, weighted = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    mass += f.mass[i];
    weighted += f.mass[i] * fluid.material.eos.pressure(f.rho[i]);
  }
  return weighted / mass;
}

// Least squares p ~ level + gradient . (x - origin) over the particles in the domain, origin their
// centroid (which makes level their mean pressure and decouples it from the gradient's normal
// equations): gradient = C^-1 s, C = sum (x - origin)(x - origin)^T, s = sum (x - origin) p, over
// the fitted axes. An axis the particles do not span (its variance below (1e-6 of the extent)^2
// of the other) is left unfitted.
ReferencePressure linear_fit(const FluidBody& fluid) {
  const FluidParticles& f = fluid.particles;
  ReferencePressure fit;
  Real count = 0.0;
  Vec2 centroid = Vec2::Zero();
  for (std::size_t i = 0; i < f.size(); ++i)
    if (f.in_domain(i)) {
      centroid += f.pos[i];
      fit.level += fluid.material.eos.pressure(f.rho[i]);
      count += 1.0;
    }
  if (count == 0.0) return {};
  fit.origin = centroid / count;
  fit.level /= count;
  Mat2 moment = Mat2::Zero();
  Vec2 weighted = Vec2::Zero();
  for (std::size_t i = 0; i < f.size(); ++i)
    if (f.in_domain(i)) {
      const Vec2 d = (f.pos[i] - fit.origin).cwiseProduct(fluid.non_periodic_axes);
      moment += d * d.transpose();
      weighted += d * fluid.material.eos.pressure(f.rho[i]);
    }
  const Real largest = moment.diagonal().maxCoeff();
  if (largest <= 0.0) return fit;
  for (int axis = 0; axis < 2; ++axis)
    if (moment(axis, axis) <= 1e-12 * largest) {  // unspanned: fit along the other axis only
      moment.row(axis).setZero();
      moment.col(axis).setZero();
      moment(axis, axis) = 1.0;
      weighted[axis] = 0.0;
    }
  fit.gradient = moment.inverse() * weighted;
  return fit;
}

}  // namespace

void update_reference_pressure(FluidBody& fluid) {
  if (fluid.particles.size() == 0) {
    fluid.reference = {};
    return;
  }
  switch (fluid.options.pressure_reference) {
    case PressureReference::Mean: fluid.reference = {mean_pressure(fluid)}; return;
    case PressureReference::Linear: fluid.reference = linear_fit(fluid); return;
    default: fluid.reference = {}; return;
  }
}

}  // namespace mrsph
