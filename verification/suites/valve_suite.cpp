// verify --suite valve: pulsatile flow through venous valve leaflets (paper section 4.3), Wo = 1, 5, 10.
// Checks the paper states: the leaflets oscillate with the period of the inflow, with an amplitude
// that grows with Wo; and that the inflow boundary imposes the analytic Womersley profile; and that the
// leaflets, in contact, never pass into each other (closest particles at least half a solid spacing).
//   inflow     centre-line velocity in the buffer against the analytic profile (relative RMS)
//   leaflets   free end of the top leaflet after the first period: the period of its main motion
//              (the displacement component with the larger range), counted as switches between
//              its open and flipped states (switching_period; the leaflet flips over with the
//              reversing flow, so the signal is square-wave-like with spikes at the flips, and
//              mean crossings would count its wobble as cycles); amplitude: half the range between
//              the 5th and 95th percentiles of x and of y (robust to the spikes at the switches; a
//              mean-crossing amplitude needs two clean cycles and found none on the Wo = 1 signal).
//              The paper's amplitude growth is checked on y, the opening of the valve.
// Full: t = 2.0 s (3.3 periods), snapshot at 2.0 s (von Mises stress, fluid velocity); the three
// cases run concurrently with --jobs > 1. Quick: Wo = 10
// to t = 0.05 s: the profile, and the leaflets opening with the forward flow.
#include "suites/valve_suite.hpp"

#include "boundary/womersley_profile.hpp"
#include "io/csv_table.hpp"
#include "metrics/signal_metrics.hpp"
#include "observers/snapshot.hpp"
#include "suites/scene_run.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

namespace mrsph::verification {

namespace {

WomersleyProfile inflow_profile(const LoadedScene& scene) {
  const ParameterTable& p = scene.parameters;
  WomersleyProfile w;
  w.channel_height = p.at("D");
  w.pressure_gradient_amplitude = p.at("A");
  w.angular_frequency = p.at("omega");
  w.density = p.at("rho");
  w.kinematic_viscosity = p.at("nu");
  return w;
}

// The inflow's centre velocity against the Womersley profile: relative RMS over the run.
double inflow_relative_rms(const ObserverSeries& s, const WomersleyProfile& analytic) {
  double e2 = 0.0, r2 = 0.0;
  for (std::size_t k = 0; k < s.time.size(); ++k) {
    const double ua = analytic.velocity(0.5 * analytic.channel_height, s.time[k]);
    e2 += (s.values[k][0] - ua) * (s.values[k][0] - ua);
    r2 += ua * ua;
  }
  return r2 > 0 ? std::sqrt(e2 / r2) : NAN;
}

// The top tip's motion: final displacement, switching period and amplitudes, mean-crossing statistics.
void measure_tip(const ObserverSeries& s, double T, Json& m) {
  std::vector<double> dx, dy;
  for (const auto& row : s.values) { dx.push_back(1000.0 * row[0]); dy.push_back(1000.0 * row[1]); }
  m["final_dx_mm"] = dx.back();
  m["final_dy_mm"] = dy.back();
  const auto switch_x = switching_period(s.time, dx, T), switch_y = switching_period(s.time, dy, T);
  if (switch_x && switch_y) {  // the leaflet's main motion: the component with the larger range
    const bool x_main = switch_x->high_level - switch_x->low_level > switch_y->high_level - switch_y->low_level;
    const SwitchingPeriod& main = x_main ? *switch_x : *switch_y;
    if (std::isfinite(main.period)) m["period_s"] = main.period;
    m["period_component"] = x_main ? "x" : "y";
    m["period_switches"] = main.switches;
  }
  if (switch_x) m["amplitude_x_mm"] = 0.5 * (switch_x->high_level - switch_x->low_level);
  if (switch_y) m["amplitude_y_mm"] = 0.5 * (switch_y->high_level - switch_y->low_level);
  if (const auto sy = oscillation_stats(s.time, dy, T)) {
    m["mean_crossing_period_y_s"] = 1.0 / sy->frequency;
    m["mean_crossing_amplitude_y_mm"] = sy->amplitude;
    m["mean_y_mm"] = sy->mean;
    m["cycles"] = sy->cycles;
  }
}

void run_case(const SuiteContext& ctx, double wo, double end_time, SuiteRun& record) {
  if (ctx.log) ctx.log(fmt::format("valve: Wo = {:g} to t = {:g} s", wo, end_time));
  CsvTable frame;
  frame.columns = {"body", "x", "y", "u", "v", "von_mises"};
  const std::string dir = fmt::format("Wo{:g}", wo);
  SceneRun run = run_scene(ctx, "venous_valve.json", {fmt::format("parameters.Wo={}", wo)}, [&](const LoadedScene&) {
    RunOptions options;
    options.end_time = end_time;
    options.sample_times = {end_time};
    options.on_sample = [&](const Simulation& sim) {
      const FluidParticles& f = sim.fluid().particles;
      for (std::size_t i = 0; i < f.size(); ++i) frame.add_row({0, f.pos[i].x(), f.pos[i].y(), f.vel[i].x(), f.vel[i].y(), 0.0});
      for (const SolidBody& s : sim.solids())
        for (std::size_t a = 0; a < s.particles.size(); ++a)
          frame.add_row({1, s.particles.pos[a].x(), s.particles.pos[a].y(), s.particles.vel[a].x(), s.particles.vel[a].y(),
                         von_mises_stress(s.material, s.particles.F[a])});
    };
    return options;
  });
  write_observer_series(run.result.series, ctx.out_dir / dir);
  frame.write(ctx.out_dir / dir / "frame_end.csv");

  const double T = run.scene.parameters.at("T");
  const WomersleyProfile analytic = inflow_profile(run.scene);
  Json& m = record.metrics;
  for (const ObserverSeries& s : run.result.series) {
    if (s.name == "inflow_centre") m["inflow_centre_relative_rms"] = inflow_relative_rms(s, analytic);
    if (s.name == "leaflet_gap") {  // smallest distance between the leaflets' particles, in solid spacings
      double closest = INFINITY, at = 0.0;
      for (std::size_t k = 0; k < s.time.size(); ++k)
        if (s.values[k][0] < closest) { closest = s.values[k][0]; at = s.time[k]; }
      m["closest_leaflet_gap_dp"] = closest / run.scene.parameters.at("dp_solid");
      m["closest_leaflet_gap_time_s"] = at;
    }
    if (s.name == "top_tip") measure_tip(s, T, m);
  }
  record.case_name = fmt::format("Wo={:g}", wo);
  record.config = {{"womersley_number", wo}, {"end_time", end_time}, {"inflow_period", T},
                   {"kinematic_viscosity", run.scene.parameters.at("nu")}, {"scene", "venous_valve.json"}};
  record.cost = cost_json(run);
  record.compressibility = compressibility_record(run);
  record.diverged = run.result.divergence.has_value();
  record.divergence = divergence_record(run);
}

double metric(const SuiteRun& r, const char* name) { return r.metrics.value(name, double(NAN)); }

}  // namespace

SuiteSummary run_valve_suite(const SuiteContext& ctx) {
  SuiteSummary summary("valve", ctx.quick, ctx.threads);
  const std::vector<double> numbers = ctx.quick ? std::vector<double>{10.0} : std::vector<double>{1.0, 5.0, 10.0};
  const double end_time = ctx.quick ? 0.05 : 2.0;
  // The cases are independent: with --jobs > 1 they run concurrently, one thread each.
  std::vector<SuiteRun> records(numbers.size());
  run_cases(ctx, numbers.size(), [&](const SuiteContext& case_ctx, std::size_t k) {
    run_case(case_ctx, numbers[k], end_time, records[k]);
  });
  std::map<double, const SuiteRun*> results;
  for (std::size_t k = 0; k < numbers.size(); ++k) results.emplace(numbers[k], &records[k]);

  for (const auto& [wo, run] : results) {
    const SuiteRun& r = *run;
    const std::string tag = fmt::format("Wo={:g}", wo);
    if (r.diverged) {
      summary.check_missing(tag + " runs", "diverged", "issue 7");
      continue;
    }
    // The buffer imposes the analytic profile; the centre probe averages over the kernel, and the
    // particles move between resets: 2 %.
    summary.check_at_most(tag + " inflow centre velocity against the analytic Womersley profile (relative RMS)",
                          metric(r, "inflow_centre_relative_rms"), 0.02, "CASES.md section 3 (GSL, erratum applied)");
    // The solid contact starts at one solid spacing; closer than half of one, the leaflets would be
    // passing into each other (they did, without the contact, at every flow reversal).
    summary.check_range(tag + " leaflets stay apart: closest distance between their particles [dp_S]",
                        metric(r, "closest_leaflet_gap_dp"), 0.5, 1e9, "solid contact (solid_contact.hpp)");
    if (ctx.quick) {
      summary.check_range(tag + " top leaflet opens with the forward flow: dy at t = 0.05 s [mm]", metric(r, "final_dy_mm"),
                          1e-3, 10.0, "the forward flow of the first quarter period pushes the leaflets apart");
    } else {
      summary.check_near(tag + " leaflet period [s] equals the inflow period", metric(r, "period_s"), 0.6, 0.03,
                         "paper section 4.3: oscillation with the period of the pulsatile inflow (5 %)");
    }
  }
  if (!ctx.quick && results.size() == 3) {
    const double a1 = metric(*results.at(1.0), "amplitude_y_mm"), a5 = metric(*results.at(5.0), "amplitude_y_mm"),
                 a10 = metric(*results.at(10.0), "amplitude_y_mm");
    summary.check_range("leaflet amplitude grows from Wo = 1 to 5 (ratio)", a5 / a1, 1.0, 1e9, "paper section 4.3");
    summary.check_range("leaflet amplitude grows from Wo = 5 to 10 (ratio)", a10 / a5, 1.0, 1e9, "paper section 4.3");
  }
  for (auto& record : records) summary.add_run(std::move(record));
  summary.write(ctx.out_dir);
  render_figures(ctx, "plot_valve.py", summary);
  summary.write(ctx.out_dir);
  return summary;
}

}  // namespace mrsph::verification
