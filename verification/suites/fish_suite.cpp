// verify --suite fish: passive flapping of a flexible fish-like body tethered at its head (paper
// section 4.4). The paper's statements, checked within 15 %: sustained flapping after t = 20, tail
// frequency about 0.74, vertical amplitudes about 0.3 (head) and 0.58 (tail, absolute: the paper's
// percentages do not match bh = 0.4), a tail Lissajous ratio about 2.25 : 1 (x to y frequency), and
// a travelling wave along the centre line (the phase of the vertical motion grows from head to tail).
// Full, to t = 200: E = 200 (the paper's code) and E* = 500 (the paper's text) at dp_S = bh/16,
// dp_F = bh/8 (the resolution of the code of the paper's time, fish_passive_flapping_in_flow.cpp:
// fluid 0.05, the fish one level finer), checked against the paper; and E = 200 at the scene's
// default dp_S = bh/8, dp_F = bh/4 (the code's later test), reported beside them as the coarse
// resolution. Cases run concurrently with --jobs > 1. Quick: E = 200 to t = 30 at the default
// resolution: stability, the symmetric start, the tether. Beside every run, the linear flutter
// theory of the same body (fish_linear_theory.hpp): its modes, and the modulus below which it flutters.
#include "suites/fish_suite.hpp"

#include "io/csv_table.hpp"
#include "metrics/signal_metrics.hpp"
#include "suites/fish_linear_theory.hpp"
#include "suites/scene_run.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

namespace mrsph::verification {

namespace {

// One run: Young's modulus and the solid resolution bh / dp_S (the fluid is twice as coarse).
struct FishCase {
  double youngs_modulus;
  int resolution;
  bool checked_against_paper;
  std::string tag() const { return fmt::format("E={:g} dp_S=bh/{}", youngs_modulus, resolution); }
  std::string directory() const { return fmt::format("E{:g}_bh{}", youngs_modulus, resolution); }
};

// The run, with the centre line (the particle row just above it) sampled over its last 5 time units.
struct FishRun {
  SceneRun run;
  CsvTable centre;  // time, x0, x, y
};

FishRun simulate(const SuiteContext& ctx, const FishCase& fish, double end_time) {
  FishRun out;
  CsvTable& centre = out.centre;
  centre.columns = {"time", "x0", "x", "y"};
  const double window = 5.0, head_y = 4.0;
  const std::vector<std::string> overrides = {fmt::format("parameters.E={}", fish.youngs_modulus),
                                              fmt::format("parameters.resolution={}", fish.resolution)};
  out.run = run_scene(ctx, "tethered_fish.json", overrides, [&](const LoadedScene& scene) {
    RunOptions options;
    options.end_time = end_time;
    for (double t = std::max(0.0, end_time - window); t <= end_time + 1e-9; t += 0.05) options.sample_times.push_back(t);
    const double dp = scene.parameters.at("dp_solid");
    options.on_sample = [&, dp](const Simulation& sim) {
      const SolidParticles& s = sim.solids()[0].particles;
      for (std::size_t a = 0; a < s.size(); ++a)
        if (std::abs(s.pos0[a].y() - (head_y + 0.5 * dp)) < 1e-9) centre.add_row({sim.time, s.pos0[a].x(), s.pos[a].x(), s.pos[a].y()});
    };
    return options;
  });
  return out;
}

// Amplitudes, frequencies, the Lissajous ratio, sustained flapping and the mean drag.
void measure_motion(const std::vector<ObserverSeries>& series, double end_time, double settle, Json& m) {
  const ObserverSeries& head = series_named(series, "head");
  const ObserverSeries& tail = series_named(series, "tail");
  const ObserverSeries& forces = series_named(series, "forces");
  if (const auto h = oscillation_stats(head.time, series_column(head, 1), settle)) {
    m["head_amplitude_y"] = h->amplitude;
    m["head_mean_y"] = h->mean;
    m["head_frequency"] = h->frequency;
  }
  if (const auto ty = oscillation_stats(tail.time, series_column(tail, 1), settle)) {
    m["tail_amplitude_y"] = ty->amplitude;
    m["tail_mean_y"] = ty->mean;
    m["tail_frequency"] = ty->frequency;
    m["tail_cycles"] = ty->cycles;
    if (const auto f = spectral_peak_frequency(tail.time, series_column(tail, 1), settle, 0.01, 3.0)) m["tail_frequency_spectral"] = *f;
    if (const auto tx = oscillation_stats(tail.time, series_column(tail, 0), settle)) m["tail_lissajous_ratio"] = tx->frequency / ty->frequency;
  }
  // Sustained flapping: half peak-to-peak of the tail's y over the last fifth of the run, about its
  // centred moving average over 4 time units (three of the paper's periods, 1 / 0.74): a slow drift
  // of the whole body off the centre line is not flapping (with the raw range, a kite drifting by
  // 1.4 in the last fifth passed this check).
  {
    const std::vector<double> y = series_column(tail, 1);
    const std::vector<double> slow = moving_average(tail.time, y, 4.0);
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t k = 0; k < y.size(); ++k)
      if (tail.time[k] >= 0.8 * end_time) { lo = std::min(lo, y[k] - slow[k]); hi = std::max(hi, y[k] - slow[k]); }
    m["tail_oscillation_last_fifth"] = 0.5 * (hi - lo);
  }
  // Mean drag after the start: the cable's tension for the linear theory's tether.
  {
    const std::vector<double> fx = series_column(forces, 0);
    double sum = 0.0;
    int n = 0;
    for (std::size_t k = 0; k < fx.size(); ++k)
      if (forces.time[k] >= settle) { sum += fx[k]; ++n; }
    m["mean_drag"] = n > 0 ? sum / n : 0.0;
  }
}

// Symmetric start: the lift stays at round-off until the instability breaks the symmetry.
double lift_before_t1(const ObserverSeries& forces) {
  double largest = 0.0;
  for (std::size_t k = 0; k < forces.time.size() && forces.time[k] < 1.0; ++k) largest = std::max(largest, std::abs(forces.values[k][1]));
  return largest;
}

// Travelling wave: phase of each centre-line particle's y at the tail frequency over the window.
void measure_travelling_wave(const CsvTable& centre, Json& m) {
  if (m.contains("tail_frequency") && !centre.rows.empty()) {
    const double w = 2.0 * M_PI * m["tail_frequency"].get<double>();
    std::map<double, std::pair<double, double>> projection;  // x0 -> (sum y cos, sum y sin)
    std::map<double, double> mean;
    std::map<double, int> count;
    for (const auto& row : centre.rows) { mean[row[1]] += row[3]; ++count[row[1]]; }
    for (auto& [x0, s] : mean) s /= count[x0];
    for (const auto& row : centre.rows) {
      auto& p = projection[row[1]];
      p.first += (row[3] - mean[row[1]]) * std::cos(w * row[0]);
      p.second += (row[3] - mean[row[1]]) * std::sin(w * row[0]);
    }
    std::vector<double> x0s, phases;
    double previous = NAN, unwrap = 0.0;
    for (const auto& [x0, p] : projection) {
      double phase = std::atan2(p.second, p.first);
      if (std::isfinite(previous)) {
        while (phase + unwrap - previous > M_PI) unwrap -= 2.0 * M_PI;
        while (phase + unwrap - previous < -M_PI) unwrap += 2.0 * M_PI;
      }
      phase += unwrap;
      previous = phase;
      x0s.push_back(x0);
      phases.push_back(phase);
    }
    if (x0s.size() > 2) {
      // Least-squares slope of phase against position: the wave number along the body.
      m["centre_line_phase_slope"] = least_squares_slope(x0s, phases);
      m["centre_line_phase_range"] = phases.back() - phases.front();
    }
  }
}

void run_case(const SuiteContext& ctx, const FishCase& fish, double end_time, SuiteRun& record) {
  const double E = fish.youngs_modulus;
  if (ctx.log) ctx.log(fmt::format("fish: {} to t = {:g}", fish.tag(), end_time));
  const FishRun fish_run = simulate(ctx, fish, end_time);
  const SceneRun& run = fish_run.run;
  const std::string dir = fish.directory();
  write_observer_series(run.result.series, ctx.out_dir / dir);
  fish_run.centre.write(ctx.out_dir / dir / "centre_line.csv");

  Json& m = record.metrics;
  const double settle = 20.0;
  measure_motion(run.result.series, end_time, settle, m);
  if (ctx.log) ctx.log(fmt::format("fish: {}: linear flutter theory", fish.tag()));
  m["linear_theory"] = fish_linear_theory(run.scene, std::max(0.0, m["mean_drag"].get<double>()), fish.checked_against_paper);
  m["lift_before_t1"] = lift_before_t1(series_named(run.result.series, "forces"));
  measure_travelling_wave(fish_run.centre, m);
  record.case_name = fish.tag();
  record.config = {{"youngs_modulus", E}, {"end_time", end_time}, {"scene", "tethered_fish.json"},
                   {"solid_damping", run.scene.parameters.at("damping")}, {"resolution", fish.resolution},
                   {"dp_solid", run.scene.parameters.at("dp_solid")}, {"dp_fluid", run.scene.parameters.at("dp_fluid")},
                   {"checked_against_paper", fish.checked_against_paper}, {"directory", dir}};
  record.cost = cost_json(run);
  record.compressibility = compressibility_record(run);
  record.diverged = run.result.divergence.has_value();
  record.divergence = divergence_record(run);
}

}  // namespace

SuiteSummary run_fish_suite(const SuiteContext& ctx) {
  SuiteSummary summary("fish", ctx.quick, ctx.threads);
  const double end_time = ctx.quick ? 30.0 : 200.0;
  const std::vector<FishCase> cases = ctx.quick
      ? std::vector<FishCase>{{200.0, 8, false}}
      : std::vector<FishCase>{{200.0, 16, true}, {500.0, 16, true}, {200.0, 8, false}};
  // The cases are independent: with --jobs > 1 they run concurrently, one thread each.
  std::vector<SuiteRun> records(cases.size());
  run_cases(ctx, cases.size(), [&](const SuiteContext& case_ctx, std::size_t k) {
    run_case(case_ctx, cases[k], end_time, records[k]);
  });

  const std::string paper = "paper section 4.4 (the values it states), within 15 % (issue 7)";
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const SuiteRun& r = records[k];
    const std::string tag = cases[k].tag();
    if (r.diverged) {
      summary.check_missing(tag + " runs", "diverged", "issue 7");
      continue;
    }
    summary.check_at_most(tag + " lift before t = 1 (symmetric start)", r.metrics.value("lift_before_t1", double(NAN)), 1e-9,
                          "the set-up is mirror-symmetric about the centre line; only round-off may break it at first");
    if (ctx.quick) continue;
    if (!cases[k].checked_against_paper) {
      summary.note_skipped(tag + " against the paper's values", "the coarse resolution, reported beside the paper's (metrics in its run record)");
      continue;
    }
    auto near = [&](const char* name, const std::string& label, double reference) {
      const double v = r.metrics.value(name, double(NAN));
      if (std::isnan(v)) summary.check_missing(tag + " " + label, "not measured (no oscillation after t = 20)", paper);
      else summary.check_near(tag + " " + label, v, reference, 0.15 * reference, paper);
    };
    summary.check_range(tag + " sustained flapping: tail half peak-to-peak about its 4-unit moving average, last fifth",
                        r.metrics.value("tail_oscillation_last_fifth", double(NAN)),
                        0.1, 10.0, "paper: sustained flapping after t = 20");
    near("tail_frequency", "tail frequency", 0.74);
    near("head_amplitude_y", "head vertical amplitude", 0.3);
    near("tail_amplitude_y", "tail vertical amplitude", 0.58);
    near("tail_lissajous_ratio", "tail Lissajous ratio (x : y frequency)", 2.25);
  }
  for (auto& record : records) summary.add_run(std::move(record));
  summary.write(ctx.out_dir);
  render_figures(ctx, "plot_fish.py", summary);
  summary.write(ctx.out_dir);
  return summary;
}

}  // namespace mrsph::verification
