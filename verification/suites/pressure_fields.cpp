// verify --suite pressure: the fields with an analytic answer.
// Still water tank (hydrostatic_tank.json, started at uniform density, the defaults a new user
// gets): over the samples after settling, particles binned by depth (10 bins over H):
//   profile_error    the largest |mean(p - rho g (H - y))| of a bin, over rho g H
//   pressure_noise   the rms of p - rho g (H - y) about its bin's mean, over rho g H
//   bottom_std       the standard deviation in time of the pressure probe at the floor, over rho g H
// Taylor-Green vortex (taylor_green.json), at t = 0.5 and 1 (velocity factor exp(-8 pi^2 t / Re)):
//   velocity_l2      sqrt(sum |v - v_a|^2 / sum |v_a|^2) over the particles
//   energy_ratio     kinetic energy over the analytic one
//   pressure_l2      sqrt(sum (p - mean p - p_a)^2 / sum p_a^2): p_a has zero mean over the box
// and over all samples (t = 0.125 ... 1):
//   effective_viscosity_ratio  nu_eff / nu, nu_eff from the least-squares slope of ln A(t) = -2 nu_eff k^2 t,
//                    A the velocity's projection on the vortex's mode, sum v . m / sum m . m with
//                    m = (-U cos kx sin ky, U sin kx cos ky): what the scheme dissipates besides the
//                    viscosity (reports/pressure.md section 27)
#include "suites/pressure_suite.hpp"

#include "io/csv_table.hpp"
#include "metrics/signal_metrics.hpp"
#include "suites/scene_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace mrsph::verification {

namespace {

constexpr int kDepthBins = 10;

struct TankStatistics {
  std::vector<double> deviation_sum = std::vector<double>(kDepthBins, 0.0);
  std::vector<double> deviation_sum2 = std::vector<double>(kDepthBins, 0.0);
  std::vector<double> depth_sum = std::vector<double>(kDepthBins, 0.0);
  std::vector<long> count = std::vector<long>(kDepthBins, 0);
};

// One tank run: its resolution H/dp and sound speed factor, with the scene's defaults (for a free
// surface, reports/pressure.md section 14: the summation's reset relaxed, the pressure force
// lattice-corrected, the pair geometry refreshed) or, reported beside them, the paper's options.
struct TankCase {
  int resolution, factor;
  bool paper_options = false;
};

SuiteRun run_tank(const SuiteContext& ctx, const TankCase& c, double settle, double end_time, CsvTable& profile) {
  const int resolution = c.resolution, factor = c.factor;
  const std::string name = fmt::format("tank H/dp={} c={}sqrt(2gH){}", resolution, factor,
                                       c.paper_options ? " paper's options (full summation, uncorrected pressure force, cached pair geometry)" : "");
  if (ctx.log) ctx.log("pressure: " + name);
  TankStatistics stats;
  double rho_g = 0.0, H = 0.0;
  FluidOptions used;  // the options the run resolved
  std::vector<std::string> overrides{fmt::format("parameters.resolution={}", resolution),
                                     fmt::format("parameters.sound_speed_factor={}", factor)};
  if (c.paper_options)
    for (const char* o : {"fluid.density_relaxation=1", "fluid.pressure_lattice_correction=false", "fluid.refresh_pair_geometry=false"})
      overrides.push_back(o);
  SceneRun run = run_scene(ctx, "hydrostatic_tank.json", overrides,
                           [&](const LoadedScene& scene) {
                             rho_g = scene.parameters.at("rho") * scene.parameters.at("g");
                             H = scene.parameters.at("H");
                             used = scene.simulation->fluid().options;
                             RunOptions options;
                             options.end_time = end_time;
                             for (double t = settle; t <= end_time + 1e-9; t += 0.1) options.sample_times.push_back(t);
                             options.on_sample = [&](const Simulation& sim) {
                               const FluidParticles& f = sim.fluid().particles;
                               for (std::size_t i = 0; i < f.size(); ++i) {
                                 const double y = f.pos[i].y();
                                 const int bin = std::clamp(static_cast<int>(y / H * kDepthBins), 0, kDepthBins - 1);
                                 const double deviation = f.p[i] - rho_g * (H - y);
                                 stats.deviation_sum[bin] += deviation;
                                 stats.deviation_sum2[bin] += deviation * deviation;
                                 stats.depth_sum[bin] += H - y;
                                 ++stats.count[bin];
                               }
                             };
                             return options;
                           });
  write_observer_series(run.result.series, ctx.out_dir / fmt::format("tank_res{}_c{}{}", resolution, factor, c.paper_options ? "_paper" : ""));

  SuiteRun r;
  r.case_name = name;
  r.config = {{"resolution", resolution}, {"sound_speed_factor", factor}, {"settle_time", settle}, {"end_time", end_time},
              {"refresh_pair_geometry", used.refresh_pair_geometry}, {"density_relaxation", used.density_relaxation},
              {"pressure_lattice_correction", used.pressure_lattice_correction}, {"scene", "hydrostatic_tank.json"}};
  r.cost = cost_json(run);
  r.compressibility = compressibility_record(run);
  r.diverged = run.result.divergence.has_value();
  r.divergence = divergence_record(run);
  if (r.diverged) return r;
  const double scale = rho_g * H;
  double worst = 0.0, noise2 = 0.0;
  long samples = 0;
  for (int b = 0; b < kDepthBins; ++b) {
    if (stats.count[b] == 0) continue;
    const double n = static_cast<double>(stats.count[b]), mean = stats.deviation_sum[b] / n;
    worst = std::max(worst, std::abs(mean) / scale);
    noise2 += stats.deviation_sum2[b] - n * mean * mean;
    samples += stats.count[b];
    const double depth = stats.depth_sum[b] / n;
    profile.add_row({static_cast<double>(resolution), static_cast<double>(factor), used.refresh_pair_geometry ? 1.0 : 0.0,
                     used.density_relaxation, used.pressure_lattice_correction ? 1.0 : 0.0, depth / H,
                     (rho_g * depth + mean) / scale, rho_g * depth / scale});
  }
  const WindowStats bottom = window_stats(series_named(run.result.series, "bottom"), 0, settle);
  r.metrics = {{"profile_error", worst}, {"pressure_noise", samples > 0 ? std::sqrt(noise2 / samples) / scale : NAN},
               {"bottom_mean", bottom.mean / scale}, {"bottom_std", bottom.std / scale}};
  return r;
}

// One vortex run: particles per wavelength L/dp, sound speed factor c / U, Reynolds number.
struct VortexCase {
  int resolution, factor, reynolds = 100;
  double advection_cfl = kPaperAdvectionCfl;
};

struct VortexRun : VortexCase {
  SuiteRun record;
};

// nu_eff / nu from the mode's amplitude A(t_s) at the samples: the least-squares slope of ln A
// against t is -2 nu_eff k^2 (the vortex's viscous decay exp(-2 nu k^2 t)).
double effective_viscosity_ratio(const std::vector<double>& t, const std::vector<double>& amplitude, double nu, double k) {
  std::vector<double> log_amplitude;
  for (double a : amplitude) log_amplitude.push_back(a > 0.0 ? std::log(a) : NAN);
  return -least_squares_slope(t, log_amplitude) / (2.0 * nu * k * k);
}

void run_vortex(const SuiteContext& ctx, VortexRun& out, CsvTable& decay) {
  const bool scene_cfl = out.advection_cfl == kPaperAdvectionCfl;
  const std::string name = (out.reynolds == 100 ? fmt::format("Taylor-Green L/dp={} c={}U", out.resolution, out.factor)
                                                : fmt::format("Taylor-Green Re={} L/dp={} c={}U", out.reynolds, out.resolution, out.factor)) +
                           (scene_cfl ? "" : fmt::format(" advection CFL {:g}", out.advection_cfl));
  if (ctx.log) ctx.log("pressure: " + name);
  Json samples = Json::array();
  std::vector<double> sample_times, amplitudes;
  double nu_used = NAN, k_used = NAN;
  std::vector<std::string> overrides{fmt::format("parameters.resolution={}", out.resolution),
                                     fmt::format("parameters.sound_speed_factor={}", out.factor), fmt::format("parameters.Re={}", out.reynolds)};
  if (!scene_cfl) overrides.push_back(fmt::format("fluid.advection_cfl={}", out.advection_cfl));
  SceneRun run = run_scene(ctx, "taylor_green.json", overrides,
                           [&](const LoadedScene& scene) {
                             const double U = scene.parameters.at("U"), k = scene.parameters.at("k");
                             const double nu = U * scene.parameters.at("L") / scene.parameters.at("Re");  // density 1
                             nu_used = nu, k_used = k;
                             RunOptions options;
                             for (int s = 1; s <= 8; ++s) options.sample_times.push_back(0.125 * s);
                             options.on_sample = [&, U, k, nu](const Simulation& sim) {
                               const FluidParticles& f = sim.fluid().particles;
                               const double t = sim.time, factor = std::exp(-2.0 * nu * k * k * t);
                               double p_mean = 0.0;
                               for (double p : f.p) p_mean += p;
                               p_mean /= static_cast<double>(f.size());
                               double e2 = 0.0, a2 = 0.0, energy = 0.0, pe2 = 0.0, pa2 = 0.0, vm = 0.0, mm = 0.0;
                               for (std::size_t i = 0; i < f.size(); ++i) {
                                 const double x = f.pos[i].x(), y = f.pos[i].y();
                                 const Vec2 mode(-U * std::cos(k * x) * std::sin(k * y), U * std::sin(k * x) * std::cos(k * y));
                                 const Vec2 va = mode * factor;
                                 vm += f.vel[i].dot(mode);
                                 mm += mode.squaredNorm();
                                 const double pa = -0.25 * U * U * (std::cos(2 * k * x) + std::cos(2 * k * y)) * factor * factor;
                                 e2 += (f.vel[i] - va).squaredNorm();
                                 a2 += va.squaredNorm();
                                 energy += f.vel[i].squaredNorm();
                                 pe2 += (f.p[i] - p_mean - pa) * (f.p[i] - p_mean - pa);
                                 pa2 += pa * pa;
                               }
                               const double vl2 = std::sqrt(e2 / a2), ratio = energy / a2, pl2 = std::sqrt(pe2 / pa2);
                               const double amplitude = vm / mm;
                               sample_times.push_back(t);
                               amplitudes.push_back(amplitude);
                               samples.push_back({{"time", t}, {"velocity_l2", vl2}, {"energy_ratio", ratio}, {"pressure_l2", pl2},
                                                  {"mode_amplitude", amplitude}});
                               decay.add_row({static_cast<double>(out.reynolds), static_cast<double>(out.resolution), static_cast<double>(out.factor),
                                              out.advection_cfl, t, vl2, ratio, pl2, amplitude / factor});
                             };
                             return options;
                           });
  SuiteRun& r = out.record;
  r.case_name = name;
  r.config = {{"resolution", out.resolution}, {"sound_speed_factor", out.factor}, {"Re", out.reynolds},
              {"advection_cfl", out.advection_cfl}, {"scene", "taylor_green.json"}};
  r.cost = cost_json(run);
  r.compressibility = compressibility_record(run);
  r.diverged = run.result.divergence.has_value();
  r.divergence = divergence_record(run);
  for (const Json& s : samples) {
    const double t = s["time"].get<double>();
    const std::string at = std::abs(t - 0.5) < 1e-6 ? "_t0.5" : std::abs(t - 1.0) < 1e-6 ? "_t1" : "";
    if (at.empty()) continue;
    for (const char* m : {"velocity_l2", "energy_ratio", "pressure_l2"}) r.metrics[std::string(m) + at] = s[m];
  }
  r.metrics["effective_viscosity_ratio"] = effective_viscosity_ratio(sample_times, amplitudes, nu_used, k_used);
  r.metrics["samples"] = samples;
}

// A viscous vortex decays at a rate that does not depend on the time step. The paper's summation,
// once per advection step, does not keep to that: at Re = 200, L/dp = 40, c = 10 U nu_eff / nu is
// 0.94 / 1.00 at advection CFL 0.25 / 0.125, and 1.071 / 1.052 without the reset (reports/pressure.md
// section 36). 2 %: what the rest of the scheme's time error moves it by between these steps
// (0.2-1.9 % without the reset at c = 10 and 20 U, L/dp = 40 and 80; 4.2 % at c = 40 U, L/dp = 40).
// Fails today.
void check_step_independence(SuiteSummary& summary, const std::vector<VortexRun>& runs, const VortexRun& r, const std::string& source) {
  for (const VortexRun& paper : runs)
    if (paper.advection_cfl == kPaperAdvectionCfl && paper.reynolds == r.reynolds && paper.resolution == r.resolution && paper.factor == r.factor)
      check_at_most_or_missing(summary, fmt::format("{}: nu_eff / nu against advection CFL {:g}'s", r.record.case_name, kPaperAdvectionCfl),
                               std::abs(run_metric(r.record, "effective_viscosity_ratio") - run_metric(paper.record, "effective_viscosity_ratio")),
                               0.02, source + "; a viscous decay is independent of the time step");
}

}  // namespace

void run_hydrostatic_tank(const SuiteContext& ctx, SuiteSummary& summary) {
  // Settling: the column, started at uniform density, breathes at the acoustic period 4 H / c
  // (0.04 s); the momentum dissipation damps it within about a second.
  const double settle = ctx.quick ? 1.0 : 1.5, end_time = ctx.quick ? 2.0 : 3.0;
  // Reported beside the checked defaults: the paper's options at the checked resolution.
  const std::vector<TankCase> plan =
      ctx.quick ? std::vector<TankCase>{{20, 10}, {20, 10, true}}
                : std::vector<TankCase>{{20, 10}, {40, 10}, {80, 10}, {40, 20}, {40, 10, true}};
  CsvTable profile;
  profile.columns = {"resolution", "sound_speed_factor", "refresh_pair_geometry", "density_relaxation",
                     "pressure_lattice_correction", "depth_over_H", "pressure_over_rho_g_H",
                     "hydrostatic_over_rho_g_H"};
  std::vector<SuiteRun> records(plan.size());
  for (std::size_t k = 0; k < plan.size(); ++k) records[k] = run_tank(ctx, plan[k], settle, end_time, profile);
  profile.write(ctx.out_dir / "tank_profiles.csv");
  const std::string source = "hydrostatics: p = rho g (H - y); tolerances of issue 17";
  if (ctx.quick) {
    // 20 particles over the depth: the time-mean pressure must be hydrostatic to 5 % of rho g H.
    check_at_most_or_missing(summary, "tank H/dp=20: largest depth-bin error of the mean pressure (of rho g H)",
                             run_metric(records[0], "profile_error"), 0.05, source + " (coarse: 5 %)");
  } else {
    check_at_most_or_missing(summary, "tank H/dp=40: largest depth-bin error of the mean pressure (of rho g H)",
                             run_metric(records[1], "profile_error"), 0.01, source);
    check_at_most_or_missing(summary, "tank H/dp=40: pressure noise about the hydrostatic profile (of rho g H)",
                             run_metric(records[1], "pressure_noise"), 0.02, source);
  }
  for (SuiteRun& r : records) summary.add_run(std::move(r));
}

void run_taylor_green(const SuiteContext& ctx, SuiteSummary& summary) {
  // Re = 100 at c = 10, 20, 40 U; and Re = 200, CFD3's, where the scheme's own dissipation shows
  // against the smaller viscosity (reports/pressure.md section 27): quick at 20 particles per
  // wavelength (about CFD3's D/dp), full at 40.
  const std::vector<VortexCase> plan =
      ctx.quick ? std::vector<VortexCase>{{50, 10}, {50, 20}, {50, 40}, {20, 10, 200}, {20, 20, 200}, {20, 40, 200}}
                : std::vector<VortexCase>{{50, 10}, {100, 10}, {200, 10}, {100, 20}, {100, 40}, {40, 10, 200}, {40, 20, 200}, {40, 40, 200},
                                          {40, 10, 200, kPaperAdvectionCfl / 2.0}};
  std::vector<VortexRun> runs;
  for (const VortexCase& c : plan) runs.push_back(VortexRun{c, {}});
  CsvTable decay;
  decay.columns = {"Re", "resolution", "sound_speed_factor", "advection_cfl", "time", "velocity_l2", "energy_ratio", "pressure_l2",
                   "mode_amplitude_over_viscous"};
  for (VortexRun& r : runs) run_vortex(ctx, r, decay);
  decay.write(ctx.out_dir / "taylor_green_decay.csv");
  const std::string source = "Taylor & Green (1937): the analytic decaying vortex; tolerances of issue 17 and reports/pressure.md";
  for (const VortexRun& r : runs) {
    if (r.reynolds != 100) {
      // The vortex decays by its viscosity: nu_eff within 5 % of nu, at the paper's c = 10 U (quick
      // and full) and at every c in full mode (the incompressible limit must not add dissipation;
      // section 27's runs give 0.94 / 0.99 / 1.27 at c = 10 / 20 / 40 U, L/dp = 40, over this window:
      // c = 10 and 40 U fail in full mode, the summation's reset feeding and draining the vortex).
      // 5 %: CFD3's wake at this Re lost two thirds of its shedding (1.15 -> 0.36) when a density
      // rule raised nu_eff by 13 % (section 27); a few per cent is what its results can bear.
      if (r.factor == 10 || !ctx.quick)
        check_relative_or_missing(summary, fmt::format("{}: effective viscosity / viscosity", r.record.case_name),
                                  run_metric(r.record, "effective_viscosity_ratio"), 1.0, 0.05, source);
      if (r.advection_cfl != kPaperAdvectionCfl) check_step_independence(summary, runs, r, source);
      continue;
    }
    // Quick: c = 10 and 20 U; c = 40 U is reported beside them (its summation-density pressure noise
    // takes 6 % of the kinetic energy by t = 1 at 50 particles per wavelength: reports/pressure.md).
    const bool checked = ctx.quick ? r.factor <= 20 : r.resolution == 100;
    if (!checked) continue;
    // The velocity field within 5 % (quick, 50 particles per wavelength) or 2 % (full, 100) of the
    // analytic one at t = 1: the vortex's decay is viscous, not numerical.
    check_at_most_or_missing(summary, fmt::format("{}: velocity L2 error at t = 1", r.record.case_name),
                             run_metric(r.record, "velocity_l2_t1"), ctx.quick ? 0.05 : 0.02, source);
    // The pressure field within 10 % at t = 0.5 in full mode: what weakly compressible SPH with
    // density diffusion reaches at 100 particles per wavelength (Antuono et al. 2010, Sun et al. 2017).
    if (!ctx.quick)
      check_at_most_or_missing(summary, fmt::format("{}: pressure L2 error at t = 0.5", r.record.case_name),
                               run_metric(r.record, "pressure_l2_t0.5"), 0.10, source);
  }
  for (VortexRun& r : runs) summary.add_run(std::move(r.record));
}

}  // namespace mrsph::verification
