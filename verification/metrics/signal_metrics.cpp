#include "metrics/signal_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace mrsph::verification {

double interpolate(const std::vector<double>& t, const std::vector<double>& y, double s) {
  if (t.empty()) throw std::invalid_argument("interpolate: empty signal");
  if (s <= t.front()) return y.front();
  if (s >= t.back()) return y.back();
  const auto it = std::upper_bound(t.begin(), t.end(), s);
  const std::size_t k = static_cast<std::size_t>(it - t.begin());
  const double w = (s - t[k - 1]) / (t[k] - t[k - 1]);
  return (1.0 - w) * y[k - 1] + w * y[k];
}

double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = std::min(x.size(), y.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t k = 0; k < n; ++k) sx += x[k], sy += y[k], sxx += x[k] * x[k], sxy += x[k] * y[k];
  const double denominator = static_cast<double>(n) * sxx - sx * sx;
  if (n < 2 || denominator == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return (static_cast<double>(n) * sxy - sx * sy) / denominator;
}

std::vector<double> moving_average(const std::vector<double>& t, const std::vector<double>& y, double window) {
  std::vector<double> out(y.size());
  std::size_t lo = 0, hi = 0;
  double sum = 0.0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    while (hi < y.size() && t[hi] <= t[k] + 0.5 * window) sum += y[hi++];
    while (t[lo] < t[k] - 0.5 * window) sum -= y[lo++];
    out[k] = sum / static_cast<double>(hi - lo);
  }
  return out;
}

namespace {

double mean_of(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / v.size(); }
double spread_of(const std::vector<double>& v) {
  if (v.size() < 2) return 0.0;
  const double m = mean_of(v);
  double s = 0.0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / (v.size() - 1));
}

// Time-weighted (trapezoidal) mean of y over the samples [first, last).
double time_mean(const std::vector<double>& t, const std::vector<double>& y, std::size_t first, std::size_t last) {
  double area = 0.0;
  for (std::size_t k = first + 1; k < last; ++k) area += 0.5 * (y[k] + y[k - 1]) * (t[k] - t[k - 1]);
  const double span = t[last - 1] - t[first];
  return span > 0.0 ? area / span : y[first];
}

}  // namespace

std::optional<OscillationStats> oscillation_stats(const std::vector<double>& t, const std::vector<double>& y,
                                                  double settle_time) {
  if (t.size() != y.size()) throw std::invalid_argument("oscillation_stats: t and y differ in length");
  const std::size_t first = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), settle_time) - t.begin());
  if (t.size() - first < 8) return std::nullopt;
  OscillationStats stats;
  std::vector<double> crossings;  // times of up-crossings of the mean
  std::vector<std::size_t> crossing_index;
  auto find_crossings = [&] {
    crossings.clear();
    crossing_index.clear();
    for (std::size_t k = first + 1; k < t.size(); ++k) {
      const double a = y[k - 1] - stats.mean, b = y[k] - stats.mean;
      if (a < 0.0 && b >= 0.0) {
        crossings.push_back(t[k - 1] + (t[k] - t[k - 1]) * (-a) / (b - a));
        crossing_index.push_back(k);
      }
    }
  };
  // The mean over the whole window is biased by a partial cycle; take it again over whole cycles
  // (first to last up-crossing) and find the crossings of that mean.
  stats.mean = time_mean(t, y, first, t.size());
  find_crossings();
  if (crossings.size() < 3) return std::nullopt;
  stats.mean = time_mean(t, y, crossing_index.front() - 1, crossing_index.back());
  find_crossings();
  if (crossings.size() < 3) return std::nullopt;
  std::vector<double> amplitudes, frequencies;
  for (std::size_t c = 0; c + 1 < crossings.size(); ++c) {
    const auto lo = y.begin() + static_cast<long>(crossing_index[c] - 1);
    const auto hi = y.begin() + static_cast<long>(crossing_index[c + 1]);
    const auto [mn, mx] = std::minmax_element(lo, hi);
    amplitudes.push_back(0.5 * (*mx - *mn));
    frequencies.push_back(1.0 / (crossings[c + 1] - crossings[c]));
  }
  stats.cycles = static_cast<int>(amplitudes.size());
  stats.amplitude = mean_of(amplitudes);
  stats.amplitude_spread = spread_of(amplitudes);
  stats.frequency = (crossings.size() - 1) / (crossings.back() - crossings.front());
  stats.frequency_spread = spread_of(frequencies);
  return stats;
}

namespace {

// The Fourier sums of uniform samples s_k at angular frequency w per sample: sum s_k cos(w k) and
// sum s_k sin(w k).
struct FourierSums {
  double cos_sum = 0.0, sin_sum = 0.0;
};
FourierSums fourier_sums(const std::vector<double>& s, double w) {
  FourierSums out;
  for (std::size_t k = 0; k < s.size(); ++k) {
    out.cos_sum += s[k] * std::cos(w * static_cast<double>(k));
    out.sin_sum += s[k] * std::sin(w * static_cast<double>(k));
  }
  return out;
}

}  // namespace

std::optional<double> spectral_peak_frequency(const std::vector<double>& t, const std::vector<double>& y,
                                              double settle_time, double f_min, double f_max) {
  const std::size_t first = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), settle_time) - t.begin());
  if (t.size() - first < 16) return std::nullopt;
  const double t0 = t[first], t1 = t.back(), span = t1 - t0;
  if (!(span > 0.0) || span * f_min < 1.0) return std::nullopt;
  const std::size_t n = 4096;
  std::vector<double> s(n);
  const double dt = span / (n - 1);
  for (std::size_t k = 0; k < n; ++k) s[k] = interpolate(t, y, t0 + k * dt);
  const double m = mean_of(s);
  for (std::size_t k = 0; k < n; ++k) s[k] = (s[k] - m) * 0.5 * (1.0 - std::cos(2.0 * M_PI * k / (n - 1)));
  // Scan the DFT on a grid 20 times finer than 1/span, then refine by a parabola through the peak.
  const double df = 0.05 / span;
  double best_f = f_min, best_p = -1.0, prev = 0.0, next = 0.0;
  std::vector<double> power;
  for (double f = f_min; f <= f_max; f += df) {
    const FourierSums sums = fourier_sums(s, 2.0 * M_PI * f * dt);
    power.push_back(sums.cos_sum * sums.cos_sum + sums.sin_sum * sums.sin_sum);
  }
  std::size_t kbest = 0;
  for (std::size_t k = 0; k < power.size(); ++k)
    if (power[k] > best_p) { best_p = power[k]; kbest = k; }
  best_f = f_min + kbest * df;
  if (kbest > 0 && kbest + 1 < power.size()) {
    prev = power[kbest - 1];
    next = power[kbest + 1];
    const double denom = prev - 2.0 * best_p + next;
    if (denom < 0.0) best_f += 0.5 * (prev - next) / denom * df;
  }
  return best_f;
}

namespace {

// The signal's in-band discrete Fourier components, synthesised on the same samples.
std::vector<double> keep_band(const std::vector<double>& s, double span, double f_lo, double f_hi) {
  const std::size_t n = s.size();
  std::vector<double> out(n, 0.0);
  const auto m_lo = static_cast<std::size_t>(std::max(1.0, std::ceil(f_lo * span)));
  const auto m_hi = std::min(static_cast<std::size_t>(std::floor(f_hi * span)), (n - 1) / 2);
  for (std::size_t mode = m_lo; mode <= m_hi; ++mode) {
    const double w = 2.0 * M_PI * static_cast<double>(mode) / static_cast<double>(n);
    const FourierSums sums = fourier_sums(s, w);
    // A real signal's pair of bins +-m: (2 / n) (cos_sum cos + sin_sum sin).
    for (std::size_t k = 0; k < n; ++k)
      out[k] += 2.0 / static_cast<double>(n) *
                (sums.cos_sum * std::cos(w * static_cast<double>(k)) + sums.sin_sum * std::sin(w * static_cast<double>(k)));
  }
  return out;
}

}  // namespace

std::optional<UniformSignal> band_pass(const std::vector<double>& t, const std::vector<double>& y, double settle_time,
                                       double f_lo, double f_hi, double taper, std::size_t samples) {
  const std::size_t first = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), settle_time) - t.begin());
  if (t.size() < first + 16 || samples < 16 || !(taper >= 0.0 && taper < 0.5)) return std::nullopt;
  const double t0 = t[first], span = t.back() - t0;
  if (!(span > 0.0) || span * f_lo < 1.0) return std::nullopt;
  // Samples at t0 + k span / n, k < n: the discrete transform's frequencies are then m / span.
  const std::size_t n = samples, edge = static_cast<std::size_t>(taper * static_cast<double>(n));
  const double dt = span / static_cast<double>(n);
  std::vector<double> s(n);
  for (std::size_t k = 0; k < n; ++k) s[k] = interpolate(t, y, t0 + static_cast<double>(k) * dt);
  const double m = mean_of(s);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t from_end = std::min(k, n - 1 - k);
    const double w = from_end < edge ? 0.5 * (1.0 - std::cos(M_PI * static_cast<double>(from_end) / static_cast<double>(edge))) : 1.0;
    s[k] = w * (s[k] - m);
  }
  const std::vector<double> band = keep_band(s, span, f_lo, f_hi);
  UniformSignal out;
  for (std::size_t k = edge; k + edge < n; ++k) {
    out.t.push_back(t0 + static_cast<double>(k) * dt);
    out.y.push_back(band[k]);
  }
  return out;
}

std::optional<SwitchingPeriod> switching_period(const std::vector<double>& t, const std::vector<double>& y,
                                                double settle_time, double band) {
  if (t.size() != y.size()) throw std::invalid_argument("switching_period: t and y differ in length");
  const std::size_t first = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), settle_time) - t.begin());
  if (t.size() - first < 8) return std::nullopt;
  std::vector<double> sorted(y.begin() + static_cast<long>(first), y.end());
  std::sort(sorted.begin(), sorted.end());
  SwitchingPeriod out;
  out.low_level = sorted[static_cast<std::size_t>(0.05 * (sorted.size() - 1))];
  out.high_level = sorted[static_cast<std::size_t>(0.95 * (sorted.size() - 1))];
  const double range = out.high_level - out.low_level;
  if (!(range > 0.0)) return std::nullopt;
  const double lower = out.low_level + band * range, upper = out.high_level - band * range;
  bool armed = false;  // the signal has been below the lower threshold since the last switch-up
  std::vector<double> times;
  for (std::size_t k = first; k < t.size(); ++k) {
    if (y[k] < lower) armed = true;
    if (armed && k > first && y[k] > upper && y[k - 1] <= upper) {
      times.push_back(t[k - 1] + (t[k] - t[k - 1]) * (upper - y[k - 1]) / (y[k] - y[k - 1]));
      armed = false;
    }
  }
  out.switches = static_cast<int>(times.size());
  out.period = times.size() < 2 ? NAN : (times.back() - times.front()) / (times.size() - 1);
  return out;
}

std::optional<CurveComparison> compare_curves(const std::vector<double>& t_run, const std::vector<double>& y_run,
                                              const std::vector<double>& t_ref, const std::vector<double>& y_ref) {
  if (t_run.empty() || t_ref.empty()) return std::nullopt;
  CurveComparison c;
  double sum2 = 0.0;
  c.reference_peak_value = -INFINITY;
  for (std::size_t k = 0; k < t_ref.size(); ++k) {
    if (t_ref[k] < t_run.front() || t_ref[k] > t_run.back()) continue;
    const double e = interpolate(t_run, y_run, t_ref[k]) - y_ref[k];
    sum2 += e * e;
    c.max_error = std::max(c.max_error, std::abs(e));
    ++c.points;
    if (y_ref[k] > c.reference_peak_value) { c.reference_peak_value = y_ref[k]; c.reference_peak_time = t_ref[k]; }
  }
  if (c.points == 0) return std::nullopt;
  c.rms_error = std::sqrt(sum2 / c.points);
  const double lo = t_ref.front(), hi = t_ref.back();
  c.peak_value = -INFINITY;
  for (std::size_t k = 0; k < t_run.size(); ++k)
    if (t_run[k] >= lo && t_run[k] <= hi && y_run[k] > c.peak_value) { c.peak_value = y_run[k]; c.peak_time = t_run[k]; }
  return c;
}

}  // namespace mrsph::verification
