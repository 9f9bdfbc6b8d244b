// verify --suite pressure: the entry, and the cylinder benchmarks of Turek & Hron (2006), CFD1-CFD3.
// Scene turek_hron_cfd.json: the FSI2 geometry with the beam as a rigid wall, in the periodic channel
// of the FSI2 scene (the benchmark's 25 D channel with a free outflow needs open boundaries). Forces:
// the force observer on cylinder + beam, each sample the force averaged over one advection step;
// metrics over a window after the flow has settled, each sample weighted by its step's duration:
//   drag_mean, lift_mean, drag_std, lift_std       (CFD1, CFD2: steady; the std is what is left unsteady)
//   drag_viscous_mean                               (the viscous pair forces' share of drag_mean; the rest
//                                                    is the pressure's: reports/pressure.md sections 15-16)
//   drag_drift, lift_drift                          (CFD1, CFD2: the mean over the window's second half
//                                                    minus that over its first: how far the mean itself
//                                                    is from settled; reports/pressure.md section 10)
//   pressure_difference_mean                        (2D-1, 2D-2: the pressure at the cylinder's front point
//                                                    minus that at its rear point, where the scene observes them)
//   strouhal, lift_amplitude, drag_amplitude        (CFD3: from the smoothed lift and drag, D = U0 = 1)
//   lift_shedding_amplitude (and _spread, _cycles), strouhal_shedding
//                                                   (CFD3: the lift's component in the shedding band)
// Plan: the ladder D/dp = 10, 20, 40 at c = 10 U0 (the paper's sound speed), with observed order,
// Richardson value and GCI; at D/dp = 20 also c = 20 and 40 U0. Quick: CFD2 at D/dp = 10, c = 10, 20 U0.
#include "suites/pressure_suite.hpp"

#include "metrics/convergence.hpp"
#include "metrics/signal_metrics.hpp"
#include "report/reference_table.hpp"
#include "suites/scene_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace mrsph::verification {

WindowStats window_stats(const ObserverSeries& s, std::size_t column, double start, double end) {
  double weight = 0.0, sum = 0.0, sum2 = 0.0;
  for (std::size_t k = 1; k < s.time.size(); ++k) {
    if (s.time[k] <= start || s.time[k] > end) continue;
    const double dt = s.time[k] - s.time[k - 1], v = s.values[k][column];
    weight += dt;
    sum += dt * v;
    sum2 += dt * v * v;
  }
  if (weight <= 0.0) return {};
  const double mean = sum / weight;
  return {mean, std::sqrt(std::max(0.0, sum2 / weight - mean * mean))};
}

namespace {

// The lift's shedding component: the lift band-passed to the case's band (CFD3's St = 0.1-0.35: a
// free cylinder's wake sheds at St = 0.212 (1 - 21.2 / Re), Roshko 1954: 0.17-0.19 at Re = 100-200;
// the confined benchmark at 0.22. The band leaves out the lines near 0.43: the drag's, and in the
// lift a second wake mode, not locked to the shedding (section 27); the channel's acoustic modes and
// the particle noise, all of which the switching count and the percentiles of the smoothed lift take
// in), its cycles' mean half peak-to-peak, their spread and count, and their frequency
// (reports/pressure.md section 26).
void add_shedding_component(const std::vector<double>& t, const std::vector<double>& lift, const BenchmarkCase& b, Json& metrics) {
  const auto band = band_pass(t, lift, b.window_start, b.shedding_band_low, b.shedding_band_high);
  if (!band) return;
  const auto cycles = oscillation_stats(band->t, band->y, band->t.front());
  if (!cycles) return;
  metrics["lift_shedding_amplitude"] = cycles->amplitude;
  metrics["lift_shedding_amplitude_spread"] = cycles->amplitude_spread;
  metrics["lift_shedding_cycles"] = cycles->cycles;
  metrics["strouhal_shedding"] = cycles->frequency;  // D = U0 = 1
}

std::string channel_description(const std::string& scene) {
  if (scene == "turek_hron_cfd.json") return "periodic, 13 D with a 2 D inflow buffer (the benchmark: 25 D, free outflow)";
  if (scene == "schaefer_turek_cylinder.json") return "the benchmark's: 22 D from a velocity inlet to a pressure outlet";
  return "the benchmark's: 25 D from a velocity inlet to a pressure outlet";
}

// The pressure at the cylinder's front point minus that at its rear point, where the scene observes
// both (Schaefer & Turek's delta p), averaged over the window: both observers sample at the same
// times, so the mean of the difference is the difference of the means.
void add_pressure_difference(const std::vector<ObserverSeries>& series, double window_start, Json& metrics) {
  const auto named = [&](const char* name) {
    return std::find_if(series.begin(), series.end(), [&](const ObserverSeries& s) { return s.name == name; });
  };
  const auto front = named("front"), rear = named("rear");
  if (front == series.end() || rear == series.end()) return;
  metrics["pressure_difference_mean"] = window_stats(*front, 0, window_start).mean - window_stats(*rear, 0, window_start).mean;
}

}  // namespace

void run_cylinder(const SuiteContext& ctx, CylinderRun& out) {
  const BenchmarkCase& b = *out.benchmark;
  const std::string name = fmt::format("{} D/dp={} c={}U0{}", b.name, out.resolution, out.sound_speed_factor,
                                       out.variant.empty() ? "" : " " + out.variant);
  if (ctx.log) ctx.log("pressure: " + name);
  std::vector<std::string> overrides{fmt::format("parameters.Re={}", b.reynolds),
                                     fmt::format("parameters.resolution={}", out.resolution),
                                     fmt::format("parameters.sound_speed_factor={}", out.sound_speed_factor)};
  overrides.insert(overrides.end(), out.overrides.begin(), out.overrides.end());
  SceneRun run = run_scene(ctx, out.scene, overrides, [&](const LoadedScene&) {
    RunOptions options;
    options.end_time = b.end_time;
    return options;
  });
  std::string series_dir = fmt::format("{}_res{}_c{}", b.name, out.resolution, out.sound_speed_factor);
  for (const char c : out.variant) series_dir += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  write_observer_series(run.result.series, ctx.out_dir / series_dir);

  SuiteRun& r = out.record;
  r.case_name = name;
  r.config = {{"benchmark", b.name}, {"reynolds", b.reynolds}, {"resolution", out.resolution},
              {"dp", run.scene.parameters.at("dp")}, {"sound_speed", run.scene.parameters.at("sound_speed")},
              {"end_time", b.end_time}, {"window_start", b.window_start}, {"scene", out.scene},
              {"channel", channel_description(out.scene)}};
  if (!out.variant.empty()) r.config["variant"] = {{"name", out.variant}, {"overrides", out.overrides}};
  r.cost = cost_json(run);
  r.compressibility = compressibility_record(run);
  r.diverged = run.result.divergence.has_value();
  r.divergence = divergence_record(run);
  if (r.diverged) return;
  const ObserverSeries& forces = series_named(run.result.series, "forces");
  const WindowStats drag = window_stats(forces, 0, b.window_start), lift = window_stats(forces, 1, b.window_start);
  r.metrics = {{"drag_mean", drag.mean}, {"drag_std", drag.std}, {"lift_mean", lift.mean}, {"lift_std", lift.std}};
  const auto viscous = std::find(forces.columns.begin(), forces.columns.end(), "fx_viscous");
  if (viscous != forces.columns.end())
    r.metrics["drag_viscous_mean"] = window_stats(forces, static_cast<std::size_t>(viscous - forces.columns.begin()), b.window_start).mean;
  add_pressure_difference(run.result.series, b.window_start, r.metrics);
  if (!b.shedding) {
    // A steady case's mean still carries the channel's slowly decaying acoustic mode (period about
    // 2 L / c) and any drift: the difference of the two halves' means says how settled it is.
    const double middle = 0.5 * (b.window_start + b.end_time);
    for (const auto& [metric, column] : {std::pair{"drag_drift", 0}, std::pair{"lift_drift", 1}})
      r.metrics[metric] = window_stats(forces, column, middle).mean - window_stats(forces, column, b.window_start, middle).mean;
    return;
  }
  // The lift carries particle-scale noise of about its own size at acoustic frequencies: averaged
  // over 0.5 (a ninth of the benchmark's period 4.55; a sinusoid of that period keeps 98 % of its
  // amplitude) before the period is counted between switches across bands a quarter in from the
  // 5th and 95th percentiles (mean crossings counted the noise: St 2-7). Amplitude: half the
  // distance between those percentiles.
  const std::vector<double> t = forces.time;
  const std::vector<double> lift_smooth = moving_average(t, series_column(forces, 1), 0.5);
  if (const auto s = switching_period(t, lift_smooth, b.window_start); s && std::isfinite(s->period)) {
    r.metrics["strouhal"] = 1.0 / s->period;  // f D / U0 with D = U0 = 1
    r.metrics["lift_amplitude"] = 0.5 * (s->high_level - s->low_level);
    r.metrics["lift_cycles"] = s->switches - 1;
  }
  if (const auto f = spectral_peak_frequency(t, lift_smooth, b.window_start, 0.1, 1.0)) r.metrics["strouhal_spectral"] = *f;
  add_shedding_component(t, series_column(forces, 1), b, r.metrics);
  const std::vector<double> drag_smooth = moving_average(t, series_column(forces, 0), 0.5);
  if (const auto s = switching_period(t, drag_smooth, b.window_start)) r.metrics["drag_amplitude"] = 0.5 * (s->high_level - s->low_level);
}

const CylinderRun* CylinderResults::find(const std::string& benchmark, int resolution, int factor,
                                         const std::string& variant) const {
  for (const CylinderRun& r : runs_)
    if (r.benchmark->name == benchmark && r.resolution == resolution && r.sound_speed_factor == factor &&
        r.variant == variant)
      return &r;
  return nullptr;
}

double CylinderResults::value(const std::string& benchmark, int resolution, int factor, const std::string& name,
                              const std::string& variant) const {
  const CylinderRun* run = find(benchmark, resolution, factor, variant);
  return run ? run_metric(run->record, name) : NAN;
}

void check_sound_speed_independence(SuiteSummary& summary, const CylinderResults& results, const std::string& benchmark,
                                    int resolution, int factor, int against, double tolerance, const std::string& source) {
  const double a = results.value(benchmark, resolution, factor, "drag_mean");
  const double b = results.value(benchmark, resolution, against, "drag_mean");
  const std::string name = fmt::format("{} drag at D/dp={}: c = {} against {} U0 (relative difference)", benchmark, resolution,
                                       factor, against);
  check_at_most_or_missing(summary, name, std::abs(a - b) / std::abs(b), tolerance, source);
}

Json convergence_table(const CylinderResults& results, const std::vector<BenchmarkCase>& cases, const std::vector<int>& ladder,
                       int factor) {
  Json table = Json::array();
  for (const BenchmarkCase& b : cases) {
    for (const char* name : {"drag_mean", "lift_mean", "pressure_difference_mean", "strouhal", "lift_amplitude", "strouhal_shedding",
                              "lift_shedding_amplitude"}) {
      Json row = {{"benchmark", b.name}, {"metric", name}, {"sound_speed_factor", factor}};
      std::vector<double> values;
      for (int res : ladder) values.push_back(results.value(b.name, res, factor, name));
      bool any = false;
      for (std::size_t k = 0; k < ladder.size(); ++k) {
        row[fmt::format("res{}", ladder[k])] = values[k];
        any = any || std::isfinite(values[k]);
      }
      if (!any) continue;
      if (values.size() == 3)
        if (const auto c = three_grid_convergence(values[0], values[1], values[2], 2.0))
          write_estimate(*c, row);
      table.push_back(row);
    }
  }
  return table;
}

double run_metric(const SuiteRun& run, const std::string& name) {
  return !run.diverged && run.metrics.contains(name) ? run.metrics[name].get<double>() : NAN;
}

void check_at_most_or_missing(SuiteSummary& summary, const std::string& name, double value, double limit,
                              const std::string& source) {
  if (!std::isfinite(value)) summary.check_missing(name, "no value: the run diverged or the metric could not be measured", source);
  else summary.check_at_most(name, value, limit, source);
}

void check_relative_or_missing(SuiteSummary& summary, const std::string& name, double value, double reference,
                               double tolerance, const std::string& source) {
  if (!std::isfinite(value)) summary.check_missing(name, "no value: the run diverged or the metric could not be measured", source);
  else summary.check_near(name, value, reference, tolerance * std::abs(reference), source);
}

void run_cylinder_benchmarks(const SuiteContext& ctx, SuiteSummary& summary) {
  const Json refs = read_project_reference(ctx.project_dir, "turek_hron_cfd.json");
  const std::string source = "Turek & Hron (2006) CFD tests, reference-data/turek_hron_cfd.json; tolerances of issue 17";
  // Settling: the inflow ramps up over t = 2 and starts the channel's acoustic mode (period 2.4 at
  // c = 10 U0: 2 L / c for L = 12 D, between the inflow buffer's 11 D and the 13 D period), which
  // decays slowly, the more slowly the finer the particles: CFD2's drag over t = 12-24 read 1.390 at
  // D/dp = 40 and 1.429 over t = 16-24 (reports/pressure.md section 10). Over t = 24-48 the means of
  // consecutive 2-unit bins of the drag stay within 1 % of their mean at D/dp = 20. CFD3 starts
  // shedding late (at D/dp = 40 from t = 25; not by t = 40 at D/dp = 20): run to t = 80 and measured
  // over its last 40 (9 periods). Since the channel drive (boundary/inflow.hpp) the ramp starts no
  // acoustic mode: CFD2's 2-unit drag bins at D/dp = 20 stay within 0.6 % of their mean from t = 10
  // (pressure.md section 13). The windows are kept as they were measured.
  const std::vector<BenchmarkCase> cases =
      ctx.quick ? std::vector<BenchmarkCase>{{"CFD2", 100.0, 20.0, 10.0, false}}
                : std::vector<BenchmarkCase>{{"CFD1", 20.0, 48.0, 24.0, false},
                                             {"CFD2", 100.0, 48.0, 24.0, false},
                                             {"CFD3", 200.0, 80.0, 40.0, true}};
  const std::vector<int> ladder = ctx.quick ? std::vector<int>{10} : std::vector<int>{10, 20, 40};
  const int checked = ctx.quick ? 10 : 20;
  const std::vector<int> factors{10, 20, 40};

  std::vector<CylinderRun> runs;
  for (const BenchmarkCase& b : cases) {
    for (int res : ladder) runs.push_back({&b, res, 10, {}});
    for (int f : factors)
      if (f != 10 && (!ctx.quick || f == 20)) runs.push_back({&b, checked, f, {}});
  }
  // Longest first, so that concurrent runs end together.
  std::stable_sort(runs.begin(), runs.end(), [](const CylinderRun& a, const CylinderRun& b) {
    const auto cost = [](const CylinderRun& r) { return r.benchmark->end_time * std::pow(r.resolution, 3) * (1.0 + 0.2 * r.sound_speed_factor); };
    return cost(a) > cost(b);
  });
  run_cases(ctx, runs.size(), [&](const SuiteContext& case_ctx, std::size_t k) { run_cylinder(case_ctx, runs[k]); });
  for (const CylinderRun& r : runs) summary.add_run(r.record);

  const CylinderResults results(runs);
  if (ctx.quick) {
    // 10 particles across the cylinder: drag -4.9 % (c = 20 U0) at D/dp = 10, +4.5 % at 20 and +2.2 %
    // at 40 in this suite's full runs; 10 % keeps the coarse case honest without asking it to be fine.
    check_relative_or_missing(summary, "CFD2 drag at D/dp=10", results.value("CFD2", 10, 10, "drag_mean"), refs["CFD2"]["drag"], 0.10,
                   source + " (coarse resolution: 10 %)");
    // Weakly compressible flow: compressibility errors are O(Mach^2), 1 % at c = 10 U0.
    check_sound_speed_independence(summary, results, "CFD2", 10, 10, 20, 0.02, source + " (O(Mach^2) = 1 % at c = 10 U0)");
  } else {
    for (const char* b : {"CFD1", "CFD2"}) {
      check_relative_or_missing(summary, fmt::format("{} drag at D/dp=20", b), results.value(b, 20, 10, "drag_mean"), refs[b]["drag"], 0.03, source);
      check_relative_or_missing(summary, fmt::format("{} lift at D/dp=20", b), results.value(b, 20, 10, "lift_mean"), refs[b]["lift"], 0.03, source);
    }
    check_sound_speed_independence(summary, results, "CFD2", 20, 20, 40, 0.02, source);
    check_sound_speed_independence(summary, results, "CFD2", 20, 10, 40, 0.05, source);
    // St and the lift amplitude of the benchmark are those of the shedding: the lift's component in
    // the shedding band (the percentiles and switches of the smoothed lift count the drag's line at
    // twice the frequency and the acoustic modes as shedding; reports/pressure.md section 26). Over
    // t = 40-200 at c = 10 U0 the amplitude of consecutive 40-unit windows spread by +-15 %: this
    // window's value is one of them, with its cycles' spread and count in the summary.
    check_relative_or_missing(summary, "CFD3 Strouhal number at D/dp=20", results.value("CFD3", 20, 10, "strouhal_shedding"), refs["CFD3"]["strouhal"], 0.02, source);
    check_relative_or_missing(summary, "CFD3 mean drag at D/dp=20", results.value("CFD3", 20, 10, "drag_mean"), refs["CFD3"]["drag_mean"], 0.03, source);
    check_relative_or_missing(summary, "CFD3 lift amplitude at D/dp=20", results.value("CFD3", 20, 10, "lift_shedding_amplitude"),
                   refs["CFD3"]["lift_amplitude"], 0.10, source);
  }
  summary.extra()["cylinder_convergence"] = convergence_table(results, cases, ladder, 10);
  summary.extra()["cylinder_reference"] = refs;
}

SuiteSummary run_pressure_suite(const SuiteContext& ctx) {
  SuiteSummary summary("pressure", ctx.quick, ctx.threads);
  run_taylor_green(ctx, summary);
  run_hydrostatic_tank(ctx, summary);
  run_submerged_cylinder(ctx, summary);
  run_cylinder_benchmarks(ctx, summary);
  run_schaefer_turek(ctx, summary);
  summary.write(ctx.out_dir);
  render_figures(ctx, "plot_pressure.py", summary);
  summary.write(ctx.out_dir);
  return summary;
}

}  // namespace mrsph::verification
