// Metrics of time signals (VERIFICATION.md, "Metrics"); unit-tested on synthetic signals.
//   oscillation:   after a settling time, the mean of the signal, the cycles between successive
//                  up-crossings of (signal - mean), and per cycle half the peak-to-peak; amplitude
//                  and frequency are averages over cycles, with their spread across cycles.
//   spectral peak: the frequency of the largest peak of a Hann-windowed Fourier transform of the
//                  uniformly resampled signal (a cross-check of the up-crossing frequency).
//   curve error:   a run compared with a reference curve at the reference's times (linear
//                  interpolation of the run): RMS and maximum absolute error; the peaks of both.
#pragma once

#include <optional>
#include <vector>

namespace mrsph::verification {

struct OscillationStats {
  double mean = 0.0;
  double amplitude = 0.0;         // mean over cycles of half the peak-to-peak
  double amplitude_spread = 0.0;  // standard deviation over cycles
  double frequency = 0.0;         // 1 / mean period
  double frequency_spread = 0.0;  // standard deviation of 1 / period over cycles
  int cycles = 0;
};

// Returns nothing if fewer than two full cycles lie after `settle_time`.
std::optional<OscillationStats> oscillation_stats(const std::vector<double>& t, const std::vector<double>& y,
                                                  double settle_time);

// Frequency of the largest spectral peak in [f_min, f_max]; nothing if the window is too short.
std::optional<double> spectral_peak_frequency(const std::vector<double>& t, const std::vector<double>& y,
                                              double settle_time, double f_min, double f_max);

// The part of y in the frequency band [f_lo, f_hi] after `settle_time`: y resampled at `samples`
// uniform times over the window, its mean removed, tapered to zero over a fraction `taper` of the
// window at each end (a cosine, so that the window's ends do not spread the lines outside the band
// into it), and only the discrete Fourier components whose frequencies k / span lie in the band kept
// (the rest of the spectrum: noise, harmonics, slow drift). Returned over the untapered middle only.
// A sinusoid in the band comes back with its amplitude (within 1 % over 9 periods, taper 0.15); of a
// line 3.6 / span outside the band 4 % leaks in (28-36 % without the taper, 3 % with 0.2, which keeps
// only 60 % of the window). Its cycles (oscillation_stats) give the amplitude of a periodic component
// per cycle, with its spread.
// Nothing if the window holds fewer than 16 samples or less than one period of f_lo.
struct UniformSignal {
  std::vector<double> t, y;
};
std::optional<UniformSignal> band_pass(const std::vector<double>& t, const std::vector<double>& y, double settle_time,
                                       double f_lo, double f_hi, double taper = 0.15, std::size_t samples = 4096);

// Period of a signal that switches between two states (a valve leaflet flipping with the flow):
// the mean time between "switch-ups", a rise above the upper threshold after a fall below the lower
// one. The thresholds lie `band` of the way in from the 5th and 95th percentiles of the signal after
// `settle_time`, so spikes at the switches and noise within a state are not counted as cycles (the
// mean-crossing count of oscillation_stats is). The period is NaN if fewer than two switch-ups
// follow; nothing is returned for fewer than 8 samples or a constant signal.
struct SwitchingPeriod {
  double period = 0.0;
  int switches = 0;           // switch-ups counted (switches - 1 periods)
  double low_level = 0.0;     // 5th and 95th percentiles after settle_time
  double high_level = 0.0;
};
std::optional<SwitchingPeriod> switching_period(const std::vector<double>& t, const std::vector<double>& y,
                                                double settle_time, double band = 0.25);

struct CurveComparison {
  double rms_error = 0.0;
  double max_error = 0.0;
  int points = 0;              // reference points inside the run's time span
  double peak_value = 0.0;     // run's maximum over the reference window
  double peak_time = 0.0;
  double reference_peak_value = 0.0;
  double reference_peak_time = 0.0;
};

std::optional<CurveComparison> compare_curves(const std::vector<double>& t_run, const std::vector<double>& y_run,
                                              const std::vector<double>& t_ref, const std::vector<double>& y_ref);

// Centred moving average of y over a time window (samples within +/- window/2): removes
// high-frequency noise (SPH pressure noise in forces) before cycles are detected.
std::vector<double> moving_average(const std::vector<double>& t, const std::vector<double>& y, double window);

// Linear interpolation of (t, y) at time s (clamped to the ends). t must be increasing.
double interpolate(const std::vector<double>& t, const std::vector<double>& y, double s);

// The least-squares slope of y against x (the straight line's); NaN with fewer than two points or
// all x equal.
double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace mrsph::verification
