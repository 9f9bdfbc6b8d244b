// verify --suite open-boundaries (open_boundary_suite.hpp). Metrics:
// Poiseuille (poiseuille_pressure.json; G = (p_in - p_out) / L, u_a(y) = G y (H - y) / (2 mu)), from
// the domain's particles in the middle half of the channel at the end (steady by then: the slowest
// start-up mode decays as exp(-pi^2 nu t / H^2), 4e-4 at t = 8):
//   flow_rate_error   (H mean(u) - Q_a) / Q_a, Q_a = G H^3 / (12 mu)
//   profile_l2        sqrt(sum (u - u_a)^2 / sum u_a^2)
//   mass_balance      |M_domain(end) - M_domain(0) - sum of the ledgers| / M_domain(0)
//   transverse_velocity_rms  sqrt(mean(v^2)) over the same particles (laminar: 0; the particles' noise)
// The same flow in a channel 10 H long at Re = 100 with both ends' pressures raised by a datum P
// (outlet_pressure): incompressible flow sees only the difference, so the flow rate must not move
// with P (reports/pressure.md section 29).
// Pulse (acoustic_pulse.json), at the probe L/4 before the outlet: the largest |p| of the pulse as
// it passes (incident) and after its return from the outlet (reflected); reflection = their ratio.
// Channel start-up (turek_hron_cfd_open.json): ramp_density_deviation, the largest |rho / rho0 - 1|
// of the domain's particles at samples every 0.25 over (0, ramp_time] (t = 0 is the lattice as cut).
#include "suites/open_boundary_suite.hpp"

#include "io/csv_table.hpp"
#include "suites/pressure_suite.hpp"
#include "suites/scene_run.hpp"
#include "suites/turek_hron_suite.hpp"

#include <fmt/format.h>

#include <cmath>

namespace mrsph::verification {

namespace {

void record_run(SuiteRun& r, const SceneRun& run, const std::string& name, Json config) {
  r.case_name = name;
  r.config = std::move(config);
  r.cost = cost_json(run);
  r.compressibility = compressibility_record(run);
  r.diverged = run.result.divergence.has_value();
  r.divergence = divergence_record(run);
}

// The profile across the channel in the middle half: mean u of the domain's particles in bins of
// dp along y, beside the analytic one.
void write_poiseuille_profile(const Simulation& sim, const LoadedScene& scene, const std::filesystem::path& path) {
  const auto& p = scene.parameters;
  const double H = p.at("H"), L = p.at("L"), mu = p.at("mu"), G = p.at("dp_in") / L, dp = p.at("dp");
  const auto bins = static_cast<std::size_t>(std::lround(H / dp));
  std::vector<double> sum(bins, 0.0);
  std::vector<long> count(bins, 0);
  const FluidParticles& f = sim.fluid().particles;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!f.in_domain(i) || f.pos[i].x() < 0.25 * L || f.pos[i].x() > 0.75 * L) continue;
    const auto k = std::min(bins - 1, static_cast<std::size_t>(std::max(0.0, f.pos[i].y() / dp)));
    sum[k] += f.vel[i].x();
    ++count[k];
  }
  CsvTable table;
  table.columns = {"y_over_H", "u", "u_analytic"};
  for (std::size_t k = 0; k < bins; ++k) {
    const double y = (k + 0.5) * dp;
    if (count[k] > 0) table.add_row({y / H, sum[k] / count[k], G * y * (H - y) / (2.0 * mu)});
  }
  table.write(path);
}

// (H mean(u) - Q_a) / Q_a over the domain's particles in the middle half of the channel.
double middle_half_flow_rate_error(const Simulation& sim, const ParameterTable& p) {
  const double H = p.at("H"), L = p.at("L"), mu = p.at("mu"), G = p.at("dp_in") / L;
  const FluidParticles& f = sim.fluid().particles;
  double sum_u = 0.0;
  long count = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!f.in_domain(i) || f.pos[i].x() < 0.25 * L || f.pos[i].x() > 0.75 * L) continue;
    sum_u += f.vel[i].x();
    ++count;
  }
  const double q_a = G * H * H * H / (12.0 * mu);
  return (H * sum_u / count - q_a) / q_a;
}

Json poiseuille_metrics(const Simulation& sim, const LoadedScene& scene, double mass0) {
  const auto& p = scene.parameters;
  const double H = p.at("H"), L = p.at("L"), mu = p.at("mu"), G = p.at("dp_in") / L;
  const FluidParticles& f = sim.fluid().particles;
  double err2 = 0.0, ref2 = 0.0, sum_v2 = 0.0;
  long count = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double x = f.pos[i].x(), y = f.pos[i].y();
    if (!f.in_domain(i) || x < 0.25 * L || x > 0.75 * L) continue;
    const double u_a = G * y * (H - y) / (2.0 * mu);
    err2 += (f.vel[i].x() - u_a) * (f.vel[i].x() - u_a);
    ref2 += u_a * u_a;
    sum_v2 += f.vel[i].y() * f.vel[i].y();
    ++count;
  }
  double ledgers = 0.0;
  for (const OpenBoundary& b : sim.open_boundaries) ledgers += b.ledger.mass_into_domain;
  return {{"flow_rate_error", middle_half_flow_rate_error(sim, scene.parameters)}, {"profile_l2", std::sqrt(err2 / ref2)},
          {"mass_balance", std::abs(domain_mass(f) - mass0 - ledgers) / mass0},
          {"transverse_velocity_rms", std::sqrt(sum_v2 / count)},
          {"particles_created", sim.open_boundaries[0].ledger.created + sim.open_boundaries[1].ledger.created},
          {"particles_deleted", sim.open_boundaries[0].ledger.deleted + sim.open_boundaries[1].ledger.deleted}};
}

// The middle half's flow rate error averaged over samples every 0.1 from `from` to the end.
struct FlowRateMean {
  double from = 0.0, sum = 0.0;
  int samples = 0;
};

// poiseuille_pressure.json with these overrides; mass0: the domain's mass at the start; mean, if
// given, accumulates the flow rate over its window.
SceneRun run_poiseuille_scene(const SuiteContext& ctx, const std::vector<std::string>& overrides, double& mass0,
                              FlowRateMean* mean = nullptr) {
  return run_scene(ctx, "poiseuille_pressure.json", overrides, [&](const LoadedScene& scene) {
    mass0 = domain_mass(scene.simulation->fluid().particles);
    RunOptions options;
    if (mean == nullptr) return options;
    for (int k = 0; mean->from + 0.1 * k < scene.run.end_time; ++k) options.sample_times.push_back(mean->from + 0.1 * k);
    options.on_sample = [mean, parameters = scene.parameters](const Simulation& sim) {
      mean->sum += middle_half_flow_rate_error(sim, parameters);
      ++mean->samples;
    };
    return options;
  });
}

SuiteRun run_poiseuille(const SuiteContext& ctx, int resolution, bool corrected) {
  const std::string name = fmt::format("Poiseuille by pressure H/dp={}{}", resolution, corrected ? "" : " (uncorrected gradient)");
  if (ctx.log) ctx.log("open-boundaries: " + name);
  double mass0 = 0.0;
  SceneRun run = run_poiseuille_scene(ctx, {fmt::format("parameters.resolution={}", resolution),
                                            fmt::format("fluid.pressure_lattice_correction={}", corrected)},
                                      mass0);
  SuiteRun r;
  record_run(r, run, name, {{"resolution", resolution}, {"pressure_lattice_correction", corrected},
                            {"scene", "poiseuille_pressure.json"}, {"end_time", run.scene.run.end_time}});
  if (r.diverged) return r;
  r.metrics = poiseuille_metrics(*run.scene.simulation, run.scene, mass0);
  write_poiseuille_profile(*run.scene.simulation, run.scene,
                           ctx.out_dir / fmt::format("poiseuille_profile_res{}{}.csv", resolution, corrected ? "" : "_uncorrected"));
  return r;
}

// Re = 100 in a channel 10 H long (H/dp = 20, c = 10 U), to t = 60: the slowest start-up mode has
// decayed to exp(-pi^2 nu t / H^2) = 0.3 % by then (0.45 % on average over t = 50-60).
// flow_rate_error_mean: the flow rate averaged over t = 50-60. Both ends hold the pressure, so the
// channel rings at its acoustic modes (f = n c / 2 L), and with the particles' noise one snapshot
// scatters by 0.1-0.5 points (std over t = 50-60, reports/pressure.md section 41); the mean over
// five periods of the fundamental (ten at c = 20 U) is what a steady flow rate is.
// linear: the linear pressure reference (an option, reports/pressure.md section 30) at c = 20 U,
// where the datum's start is a 1.25 % compression (at c = 10 U its 5 % wave sloshes undamped and
// the run turns tensile-unstable).
// advection_cfl: the fluid's advection CFL number (the scene's is the paper's 0.25).
SuiteRun run_poiseuille_datum(const SuiteContext& ctx, double datum, bool linear = false, double advection_cfl = kPaperAdvectionCfl) {
  const bool scene_cfl = advection_cfl == kPaperAdvectionCfl;
  const std::string name = fmt::format("Poiseuille by pressure Re=100 L=10H, outlet datum {:g} rho U^2{}{}", datum,
                                       linear ? ", linear reference, c=20U" : "",
                                       scene_cfl ? "" : fmt::format(", advection CFL {:g}", advection_cfl));
  if (ctx.log) ctx.log("open-boundaries: " + name);
  double mass0 = 0.0;
  std::vector<std::string> overrides{"parameters.Re=100", "parameters.L=10", "parameters.resolution=20", "end_time=60",
                                     fmt::format("parameters.outlet_pressure={}", datum)};
  if (linear) overrides.insert(overrides.end(), {R"(fluid.pressure_reference="linear")", "parameters.sound_speed_factor=20"});
  if (!scene_cfl) overrides.push_back(fmt::format("fluid.advection_cfl={}", advection_cfl));
  FlowRateMean mean{50.0};
  SceneRun run = run_poiseuille_scene(ctx, overrides, mass0, &mean);
  SuiteRun r;
  record_run(r, run, name, {{"Re", 100}, {"L_over_H", 10}, {"resolution", 20}, {"outlet_pressure", datum},
                            {"pressure_reference", linear ? "linear" : "the scene's"}, {"sound_speed_factor", linear ? 20 : 10},
                            {"advection_cfl", advection_cfl}, {"scene", "poiseuille_pressure.json"},
                            {"end_time", run.scene.run.end_time}, {"flow_rate_mean_from", mean.from}});
  if (r.diverged) return r;
  r.metrics = poiseuille_metrics(*run.scene.simulation, run.scene, mass0);
  r.metrics["flow_rate_error_mean"] = mean.samples > 0 ? mean.sum / mean.samples : NAN;
  return r;
}

double largest_abs_between(const ObserverSeries& s, double from, double to) {
  double m = 0.0;
  for (std::size_t k = 0; k < s.time.size(); ++k)
    if (s.time[k] > from && s.time[k] < to) m = std::max(m, std::abs(s.values[k][0]));
  return m;
}

SuiteRun run_pulse(const SuiteContext& ctx, double reflection_time) {
  const std::string name = fmt::format("acoustic pulse, outlet reflection_time={:g}", reflection_time);
  if (ctx.log) ctx.log("open-boundaries: " + name);
  SceneRun run = run_scene(ctx, "acoustic_pulse.json", {fmt::format("parameters.reflection_time={}", reflection_time)});
  write_observer_series(run.result.series, ctx.out_dir / fmt::format("pulse_tau{:g}", reflection_time));
  SuiteRun r;
  record_run(r, run, name, {{"reflection_time", reflection_time}, {"scene", "acoustic_pulse.json"}});
  if (r.diverged) return r;
  // The pulse peaks at the inlet at pulse_time; it passes the probe (3 L / 4) after 3 L / (4 c),
  // and returns after 5 L / (4 c); windows of +-L / (4 c) around each (the pulse lasts ~ 0.1 L / c).
  const auto& p = run.scene.parameters;
  const double L = p.at("L"), c = p.at("c"), t0 = p.at("pulse_time"), half = 0.25 * L / c;
  const ObserverSeries& probe = series_named(run.result.series, "pressure_far");
  const double incident = largest_abs_between(probe, t0 + 0.75 * L / c - half, t0 + 0.75 * L / c + half);
  const double reflected = largest_abs_between(probe, t0 + 1.25 * L / c - half, t0 + 1.25 * L / c + half);
  r.metrics = {{"incident", incident}, {"reflected", reflected}, {"reflection", reflected / incident},
               {"acoustic_pressure", p.at("rho_fluid") * c * p.at("amplitude")}};
  return r;
}

// The density along the channel at a sample: per bin of D = 1 along x, the mean and the largest
// |rho / rho0 - 1| of the domain's particles (rows: t, x of the bin's centre, mean, largest).
void add_density_along_channel(const Simulation& sim, CsvTable& table) {
  const FluidParticles& f = sim.fluid().particles;
  const double rho0 = sim.fluid().material.rho0();
  const double length = sim.open_boundaries[1].plane - sim.open_boundaries[0].plane;
  const auto bins = static_cast<std::size_t>(std::ceil(length));
  std::vector<double> sum(bins, 0.0), largest(bins, 0.0);
  std::vector<long> count(bins, 0);
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!f.in_domain(i)) continue;
    const auto k = std::min(bins - 1, static_cast<std::size_t>(std::max(0.0, f.pos[i].x() - sim.open_boundaries[0].plane)));
    sum[k] += f.rho[i] / rho0 - 1.0;
    largest[k] = std::max(largest[k], std::abs(f.rho[i] / rho0 - 1.0));
    ++count[k];
  }
  for (std::size_t k = 0; k < bins; ++k)
    if (count[k] > 0) table.add_row({sim.time, sim.open_boundaries[0].plane + k + 0.5, sum[k] / count[k], largest[k]});
}

SuiteRun run_channel_startup(const SuiteContext& ctx, int resolution, int sound_speed_factor) {
  const std::string name = fmt::format("CFD2 channel start-up D/dp={} c={}U0", resolution, sound_speed_factor);
  if (ctx.log) ctx.log("open-boundaries: " + name);
  double deviation = 0.0, near_planes = 0.0, ramp = 0.0;
  CsvTable along;
  along.columns = {"time", "x", "mean_density_deviation", "largest_density_deviation"};
  SceneRun run = run_scene(ctx, "turek_hron_cfd_open.json",
                           {fmt::format("parameters.resolution={}", resolution),
                            fmt::format("parameters.sound_speed_factor={}", sound_speed_factor)},
                           [&](const LoadedScene& scene) {
                             ramp = scene.parameters.at("ramp_time");
                             RunOptions o;
                             o.end_time = ramp;
                             for (double t = 0.25; t <= ramp + 1e-9; t += 0.25) o.sample_times.push_back(t);
                             o.on_sample = [&, taken = 0](const Simulation& sim) mutable {
                               const FluidParticles& f = sim.fluid().particles;
                               const double rho0 = sim.fluid().material.rho0();
                               if (++taken % 20 == 0) add_density_along_channel(sim, along);  // every 5 s
                               for (std::size_t i = 0; i < f.size(); ++i) {
                                 if (!f.in_domain(i)) continue;
                                 const double d = std::abs(f.rho[i] / rho0 - 1.0);
                                 deviation = std::max(deviation, d);
                                 for (const OpenBoundary& b : sim.open_boundaries)
                                   if (b.depth(f.pos[i]) > -1.0) near_planes = std::max(near_planes, d);  // within D = 1
                               }
                             };
                             return o;
                           });
  SuiteRun r;
  record_run(r, run, name, {{"resolution", resolution}, {"sound_speed_factor", sound_speed_factor},
                            {"scene", "turek_hron_cfd_open.json"}, {"ramp_time", ramp}});
  if (r.diverged) return r;
  r.metrics = {{"ramp_density_deviation", deviation}, {"ramp_density_deviation_near_planes", near_planes}};
  along.write(ctx.out_dir / fmt::format("ramp_density_res{}_c{}.csv", resolution, sound_speed_factor));
  return r;
}

void run_poiseuille_part(const SuiteContext& ctx, SuiteSummary& summary) {
  const int checked = ctx.quick ? 20 : 40;
  std::vector<SuiteRun> runs;
  if (!ctx.quick) runs.push_back(run_poiseuille(ctx, 20, true));
  runs.push_back(run_poiseuille(ctx, checked, true));
  if (!ctx.quick) runs.push_back(run_poiseuille(ctx, checked, false));
  const SuiteRun& main = runs[ctx.quick ? 0 : 1];
  const std::string source = "plane Poiseuille flow, u = G y (H - y) / (2 mu); issue 18";
  // Issue 18: within 1 % at H/dp = 40. At H/dp = 20 the same flow driven by a body force in a
  // periodic channel is 0.9 % slow at the centre (the viscous and wall operators at this
  // resolution), so quick mode allows 1.5 %.
  const double tolerance = ctx.quick ? 0.015 : 0.01;
  check_at_most_or_missing(summary, fmt::format("Poiseuille flow rate error at H/dp={}", checked),
                           std::abs(run_metric(main, "flow_rate_error")), tolerance, source);
  check_at_most_or_missing(summary, fmt::format("Poiseuille profile L2 error at H/dp={}", checked), run_metric(main, "profile_l2"),
                           tolerance, source);
  // Equal masses summed in two orders: round-off of a sum of ~1000-4000 terms.
  check_at_most_or_missing(summary, fmt::format("mass balance of the buffers at H/dp={}", checked), run_metric(main, "mass_balance"),
                           1e-12, "inflow minus outflow against the domain's mass; issue 18 (round-off)");
  for (SuiteRun& r : runs) summary.add_run(std::move(r));
}

// The outlet's pressure as a datum. At datum 0 the long channel's flow is checked as the short one's
// is (1 %). At datum 5 rho U^2 the pressure force's zero-order residue times the raised level stirs
// the particles (their transverse velocity 10 times datum 0's) and the flow rate falls by about a
// quarter (reports/pressure.md section 29): that check fails, so it is made in full mode, where
// failures are reported; quick mode records both runs' metrics (the baseline follows them) and
// checks datum 0 only.
void run_poiseuille_datum_part(const SuiteContext& ctx, SuiteSummary& summary) {
  SuiteRun zero = run_poiseuille_datum(ctx, 0.0), raised = run_poiseuille_datum(ctx, 5.0);
  const std::string source = "plane Poiseuille flow, u = G y (H - y) / (2 mu); an incompressible flow's pressure datum is free";
  // H/dp = 20 as quick mode's short channel, at Re = 100 (at the short one's Re = 10 the viscous
  // stress is ten times larger and the datum moves the flow by 0.7 % over 10 H): 1 %.
  // Each check reads the flow rate averaged over t = 50-60 (run_poiseuille_datum).
  check_at_most_or_missing(summary, "Poiseuille mean flow rate error at Re=100, L=10H, datum 0", std::abs(run_metric(zero, "flow_rate_error_mean")),
                           0.01, source);
  if (!ctx.quick)
    // Compressibility moves the flow rate by O(Mach^2) = 1 % at c = 10 U (U the centreline speed).
    check_at_most_or_missing(summary, "Poiseuille mean flow rate at datum 5 against datum 0 (Re=100, L=10H)",
                             std::abs(run_metric(raised, "flow_rate_error_mean") - run_metric(zero, "flow_rate_error_mean")), 0.01, source);
  // The linear reference at c = 20 U: a steady viscous flow rate does not depend on the density the
  // datum compresses, so what is left is compressibility, O(Mach^2) = 0.25 % at c = 20 U. It held
  // (0.09 points) while outputs cut the steps; at the scene's own steps the datum takes 1.2 points
  // averaged over t = 50-60 (reports/pressure.md section 40). At c = 20 U the paper's whole reset each
  // step stirs the particles (transverse velocity 0.009 U, 7 times c = 10 U's); relaxed to a quarter
  // per step (not the paper's method) they are 10 times calmer and the pair is 0.22 points apart
  // (section 41). Full mode, where failures are reported; quick mode records both runs' metrics,
  // which the baseline follows.
  SuiteRun linear_zero = run_poiseuille_datum(ctx, 0.0, true), linear_raised = run_poiseuille_datum(ctx, 5.0, true);
  if (!ctx.quick)
    check_at_most_or_missing(summary, "Poiseuille flow rate at datum 5 against datum 0, linear reference, c=20U (Re=100, L=10H)",
                             std::abs(run_metric(linear_raised, "flow_rate_error_mean") - run_metric(linear_zero, "flow_rate_error_mean")),
                             0.0025, source + " (O(Mach^2) at c = 20 U; reports/pressure.md sections 30, 40 and 41)");
  // A steady flow does not depend on the time step. The paper's shift, a displacement per advection
  // step, acted four times as often at a quarter of the step and broke the entering lattice up:
  // the centre velocity 0.983 -> 1.155 at CFL 0.25 -> 0.06 (reports/pressure.md section 35); so did
  // the summation's whole reset each step: five times the particles' noise and 1.2 points less flow
  // (section 41). Both now follow the CFL. What the step may still move is the compressible
  // transient's O(Mach^2) = 1 % at c = 10 U. In quick mode too, as the guard of that scaling: the
  // quarter step's run takes about 50 s of one core.
  SuiteRun quarter = run_poiseuille_datum(ctx, 0.0, false, kPaperAdvectionCfl / 4.0);
  check_at_most_or_missing(summary, "Poiseuille mean flow rate at advection CFL 0.0625 against 0.25 (Re=100, L=10H, datum 0)",
                           std::abs(run_metric(quarter, "flow_rate_error_mean") - run_metric(zero, "flow_rate_error_mean")), 0.01,
                           "a steady flow is independent of the time step; O(Mach^2) at c = 10 U");
  summary.add_run(std::move(quarter));
  summary.add_run(std::move(zero));
  summary.add_run(std::move(raised));
  summary.add_run(std::move(linear_zero));
  summary.add_run(std::move(linear_raised));
}

void run_pulse_part(const SuiteContext& ctx, SuiteSummary& summary) {
  SuiteRun fixed = run_pulse(ctx, 0.0), absorbing = run_pulse(ctx, 2.0);
  const std::string source = "plane acoustic pulse at a pressure-release end: R = -1 (linear acoustics)";
  // Fixed pressure reflects the whole pulse with its sign changed; the Riemann dissipation over
  // the extra path of L / 2 costs under 1 % here (incident amplitudes at L / 4 and 3 L / 4 agree to 0.3 %).
  check_relative_or_missing(summary, "pulse reflection at a fixed-pressure outlet", run_metric(fixed, "reflection"), 1.0, 0.05, source);
  // Weakly reflecting: p - rho c u_n held at its mean relaxed over tau = 2 (5 transit times). The
  // mean moves by (pulse duration / tau) ~ 4 % of the pulse while it passes; the extrapolation
  // samples it a kernel support inside the plane. 10 % is an order of magnitude below R = 1.
  check_at_most_or_missing(summary, "pulse reflection at a weakly reflecting outlet (tau = 2)", run_metric(absorbing, "reflection"), 0.10,
                           "characteristic outflow condition (Poinsot & Lele 1992, with a relaxed mean); issue 18");
  summary.add_run(std::move(fixed));
  summary.add_run(std::move(absorbing));
}

void run_channel_part(const SuiteContext& ctx, SuiteSummary& summary) {
  const int resolution = ctx.quick ? 10 : 20;
  SuiteRun paper_c = run_channel_startup(ctx, resolution, 10), high_c = run_channel_startup(ctx, resolution, 40);
  // Issue 18: no density deviation above 3 % anywhere during the ramp (the periodic seam opened
  // 55-61 %). At c = 10 U0 that is out of reach whatever the boundaries do: accelerating the 25 D
  // column over the benchmark's ramp needs rho L dU/dt = 2 rho U0^2 at the inlet and the
  // stagnation point adds 1.1 rho U0^2, i.e. 3 % density by themselves (reports/open-boundaries.md).
  // At c = 40 U0 that part is 16 times smaller. What the boundaries answer for is the fluid near
  // them (within D of a plane), where the seam's deficit was, and, at c = 40 U0, the whole channel
  // (until the cylinder's ring fill was fixed, fluid particles caught in a slot inside the cylinder
  // made 5-15 % there whatever c).
  check_at_most_or_missing(summary, fmt::format("largest density deviation within D of the inlet and outlet during the ramp, c = 40 U0 (D/dp={})", resolution),
                           run_metric(high_c, "ramp_density_deviation_near_planes"), 0.03, "issue 18");
  check_at_most_or_missing(summary, fmt::format("largest density deviation anywhere during the ramp, c = 40 U0 (D/dp={})", resolution),
                           run_metric(high_c, "ramp_density_deviation"), 0.03, "issue 18");
  summary.add_run(std::move(paper_c));
  summary.add_run(std::move(high_c));
}

SuiteRun run_fsi2_open(const SuiteContext& ctx) {
  const std::string name = "FSI2 case III, open channel";
  if (ctx.log) ctx.log("open-boundaries: " + name);
  SceneRun run = run_scene(ctx, "turek_hron_fsi2_open.json", {});
  write_observer_series(run.result.series, ctx.out_dir / "fsi2_open");
  SuiteRun r;
  const double end = run.scene.run.end_time, settle = 100.0;  // 20 cycles after the oscillation settled
  record_run(r, run, name, {{"scene", "turek_hron_fsi2_open.json"}, {"end_time", end}, {"settle", settle}});
  if (!r.diverged) r.metrics = fsi2_metrics(series_named(run.result.series, "tip"), series_named(run.result.series, "forces"), end, settle);
  return r;
}

// Full mode: the benchmarks in the benchmark's geometry, reported beside the periodic form
// (reports/pressure.md, turek-hron.md): CFD2 (steady; ramp to t = 20, mean over t = 25-40), CFD3
// (at D/dp = 20 the shedding becomes regular only near t = 80, 60 after the ramp ended: over t =
// 60-100 the lift's strongest line was at 0.425, twice the shedding's; mean over t = 100-140, 9
// periods) at D/dp = 20, c = 10 U0, and FSI2 case III.
void run_benchmarks_part(const SuiteContext& ctx, SuiteSummary& summary) {
  static const std::vector<BenchmarkCase> cases{{"CFD2", 100.0, 40.0, 25.0, false}, {"CFD3", 200.0, 140.0, 100.0, true}};
  std::vector<CylinderRun> runs;
  for (const BenchmarkCase& b : cases) runs.push_back({&b, 20, 10, {}, "turek_hron_cfd_open.json"});
  SuiteRun fsi2;
  run_cases(ctx, runs.size() + 1, [&](const SuiteContext& case_ctx, std::size_t k) {
    if (k == 0) run_cylinder(case_ctx, runs[1]);  // the longest first
    else if (k == 1) run_cylinder(case_ctx, runs[0]);
    else fsi2 = run_fsi2_open(case_ctx);
  });
  for (CylinderRun& r : runs) {
    r.record.case_name += " (open channel)";
    summary.add_run(std::move(r.record));
  }
  summary.add_run(std::move(fsi2));
}

}  // namespace

SuiteSummary run_open_boundary_suite(const SuiteContext& ctx) {
  SuiteSummary summary("open-boundaries", ctx.quick, ctx.threads);
  run_poiseuille_part(ctx, summary);
  run_poiseuille_datum_part(ctx, summary);
  run_pulse_part(ctx, summary);
  run_channel_part(ctx, summary);
  if (!ctx.quick) run_benchmarks_part(ctx, summary);
  summary.write(ctx.out_dir);
  render_figures(ctx, "plot_open_boundaries.py", summary);
  summary.write(ctx.out_dir);
  return summary;
}

}  // namespace mrsph::verification
