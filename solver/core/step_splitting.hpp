// Splitting an interval into steps that respect a criterion and add up to it exactly: the next
// step is remaining / ceil(remaining / criterion), so the steps of one interval are near-equal
// and the last one is exactly what remains (no tiny final step, no overshoot). For the solid this
// is the paper's kappa = [dt_ac / dt_S] + 1 sub-steps, re-evaluated every sub-step; the sub-steps
// sum to the acoustic step exactly, which momentum conservation requires (paper section 3.3).
#pragma once

#include "core/types.hpp"

#include <algorithm>
#include <cmath>

namespace mrsph {

struct SplitStep {
  Real size;
  bool last;
};

inline SplitStep split_remaining(Real remaining, Real criterion) {
  const Real pieces = std::ceil(remaining / criterion * (1.0 - 1e-12));
  if (!(pieces > 1.0)) return {remaining, true};
  return {remaining / pieces, false};
}

// The paper's Algorithm 1 for the acoustic steps of an advection step Dt: full steps of the
// criterion, each at most Dt (an explicit viscous step may have set Dt below the acoustic one),
// until their sum reaches Dt; so the last may pass Dt by less than one step, never `limit` (the
// end time: the step that reaches it is cut to land on it).
inline SplitStep full_step_towards(Real elapsed, Real Dt, Real limit, Real criterion) {
  const Real size = std::min(criterion, Dt);
  if (elapsed + size >= limit * (1.0 - 1e-12)) return {limit - elapsed, true};
  return {size, elapsed + size >= Dt * (1.0 - 1e-12)};
}

// Full acoustic steps that stay inside the advection step Dt: the step is the criterion (at most
// what remains of Dt), and the last is the one after which another of its size would pass Dt; so
// the advection step ends at or before Dt, and neither criterion is exceeded
// (reports/performance.md sections 3 and 19). An advection step cut to reach `limit` (the end
// time) is split equally instead, so that it lands on the limit.
inline SplitStep full_step_inside(Real elapsed, Real Dt, Real limit, Real criterion) {
  if (limit <= Dt * (1.0 + 1e-12)) return split_remaining(limit - elapsed, criterion);
  const Real size = std::min(criterion, Dt - elapsed);
  return {size, elapsed + 2.0 * size > Dt * (1.0 + 1e-12)};
}

}  // namespace mrsph
