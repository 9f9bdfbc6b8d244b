// verify --suite oscillating-plate: a cantilever plate released in its first bending mode
// (Gray, Monaghan & Swift 2001; CASES.md), total Lagrangian SPH, no fluid, no damping.
//   period        from up-crossings of the tip deflection, against Euler-Bernoulli (plane strain):
//                 omega^2 = E H^2 k^4 / (12 rho (1 - nu^2)), k L = 1.875
//   convergence   the period on the ladder H/dp = 4, 8, 16 (and 32 in full mode): error against the
//                 theory, and the three-grid order and Richardson value of the SPH periods
//   energy        kinetic + strain energy, its largest relative departure from the initial value
//   decay         tip amplitude of the last cycle over the first
// V_f = 0.01 is compared with the linear theory; V_f = 0.05 (tip amplitude over half the length)
// is shown as the large-deflection case; nu = 0.49 shows the solid time step stays stable.
#include "suites/oscillating_plate_suite.hpp"

#include "io/csv_table.hpp"
#include "metrics/convergence.hpp"
#include "metrics/signal_metrics.hpp"
#include "solid/solid_dynamics.hpp"
#include "suites/scene_run.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

namespace mrsph::verification {

namespace {

struct PlateCase {
  std::string material;  // saint_venant_kirchhoff | neo_hookean
  int resolution;
  double vf;
  double nu;
  double periods;
  std::string gradient_correction = "second_order";
};

struct PlateResult {
  PlateCase c;
  bool diverged = false;
  double period = NAN, theory = NAN, period_error = NAN, amplitude = NAN, decay = NAN, energy_drift = NAN;
};

std::string case_name(const PlateCase& c) {
  return fmt::format("{} H/dp={} Vf={:g} nu={:g}{}", c.material == "neo_hookean" ? "NH" : "SVK", c.resolution, c.vf, c.nu,
                     c.gradient_correction == "first_order" ? " B0" : "");
}

std::string file_stem(const PlateCase& c) {
  return fmt::format("plate_{}_res{}_vf{:g}_nu{:g}{}", c.material == "neo_hookean" ? "nh" : "svk", c.resolution, c.vf, c.nu,
                     c.gradient_correction == "first_order" ? "_b0" : "");
}

PlateResult run_case(const SuiteContext& ctx, const PlateCase& c, SuiteSummary& summary) {
  if (ctx.log) ctx.log("oscillating-plate: " + case_name(c));
  PlateResult out{c};
  CsvTable energy;
  energy.columns = {"time", "kinetic", "strain", "total"};
  const std::vector<std::string> overrides{
      fmt::format("parameters.resolution={}", c.resolution), fmt::format("parameters.Vf={}", c.vf),
      fmt::format("parameters.nu={}", c.nu), fmt::format("parameters.periods={}", c.periods),
      fmt::format("solids[0].material.model=\"{}\"", c.material),
      fmt::format("solids[0].gradient_correction=\"{}\"", c.gradient_correction)};
  SceneRun run = run_scene(ctx, "oscillating_plate.json", overrides, [&](const LoadedScene& scene) {
    out.theory = 2.0 * M_PI / scene.parameters.at("omega");
    RunOptions options;
    for (double t = 0.0; t <= scene.run.end_time; t += out.theory / 100.0) options.sample_times.push_back(t);
    options.on_sample = [&](const Simulation& sim) {
      const double k = solid_kinetic_energy(sim.solids()[0]), s = solid_strain_energy(sim.solids()[0]);
      energy.add_row({sim.time, k, s, k + s});
    };
    return options;
  });
  out.diverged = run.result.divergence.has_value();
  energy.write(ctx.out_dir / (file_stem(c) + "_energy.csv"));
  write_observer_series(run.result.series, ctx.out_dir / file_stem(c));

  const ObserverSeries& tip = run.result.series.at(0);
  std::vector<double> t = tip.time, y;
  for (const auto& v : tip.values) y.push_back(v[1]);
  if (const auto s = oscillation_stats(t, y, 0.0); s && !out.diverged) {
    out.period = 1.0 / s->frequency;
    out.period_error = out.period / out.theory - 1.0;
    // Amplitudes of the first and last whole cycles, from the extreme deflections in each.
    const double first_end = std::min(t.back(), out.period), last_start = std::max(0.0, t.back() - out.period);
    double first = 0.0, last = 0.0;
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (t[k] <= first_end) first = std::max(first, std::abs(y[k]));
      if (t[k] >= last_start) last = std::max(last, std::abs(y[k]));
    }
    out.amplitude = first;
    out.decay = last / first;
  }
  if (!energy.rows.empty()) {
    const double e0 = energy.rows.front()[3];
    double drift = 0.0;
    for (const auto& row : energy.rows) drift = std::max(drift, std::abs(row[3] - e0) / e0);
    out.energy_drift = drift;
  }

  SuiteRun record;
  record.case_name = case_name(c);
  record.config = {{"material", c.material}, {"resolution", c.resolution}, {"Vf", c.vf}, {"poisson_ratio", c.nu},
                   {"gradient_correction", c.gradient_correction},
                   {"periods", c.periods}, {"h_over_dp", run.scene.parameters.at("h_over_dp")},
                   {"dp", run.scene.parameters.at("dp")}, {"scene", "oscillating_plate.json"}};
  record.metrics = {{"period", out.period}, {"period_theory", out.theory}, {"period_error", out.period_error},
                    {"tip_amplitude", out.amplitude}, {"amplitude_decay", out.decay}, {"energy_drift", out.energy_drift}};
  record.cost = cost_json(run);
  record.compressibility = compressibility_record(run);
  record.diverged = out.diverged;
  record.divergence = divergence_record(run);
  summary.add_run(std::move(record));
  return out;
}

const std::string kTheory = "Euler-Bernoulli period, plane strain (CASES.md); issue 3 acceptance";
const std::vector<std::string> kMaterials{"saint_venant_kirchhoff", "neo_hookean"};
double periods_to_run(const SuiteContext& ctx) { return ctx.quick ? 3.5 : 5.0; }  // two whole cycles at the coarsest rung

// One material's resolution ladder: its runs, their checks (accuracy at the finest rung, energy,
// convergence) and its row of the convergence table.
Json run_material_ladder(const SuiteContext& ctx, const std::string& material, std::map<int, PlateResult>& results,
                         SuiteSummary& summary) {
  const std::vector<int> ladder = ctx.quick ? std::vector<int>{4, 8, 16} : std::vector<int>{4, 8, 16, 32};
  const double periods = periods_to_run(ctx);
  const std::string& theory = kTheory;
  // Quick mode: the whole ladder for SVK, only H/dp = 8 for Neo-Hookean.
  std::vector<int> rungs = ladder;
  if (ctx.quick && material == "neo_hookean") rungs = {8};
  if (!ctx.quick && material == "neo_hookean") rungs = {4, 8, 16};
  for (int res : rungs) results.emplace(res, run_case(ctx, {material, res, 0.01, 0.3975, periods}, summary));

  const std::string tag = material == "neo_hookean" ? "NH" : "SVK";
  const PlateResult& finest = results.rbegin()->second;
  // Within 5 % of the theory at the finest rung, when it is fine enough to ask that (H/dp >= 16).
  if (finest.c.resolution >= 16) {
    const std::string name = fmt::format("{} |period error| at H/dp={}", tag, finest.c.resolution);
    if (finest.diverged || std::isnan(finest.period_error)) summary.check_missing(name, "no period measured", theory);
    else summary.check_at_most(name, std::abs(finest.period_error), 0.05, theory);
  }
  // Energy: no damping is used, so kinetic + strain energy must be conserved; 2 % over the run
  // (issue 3 acceptance), for every rung.
  for (const auto& [res, r] : results)
    summary.check_at_most(fmt::format("{} energy drift at H/dp={}", tag, res), r.energy_drift, 0.02,
                          "issue 3 acceptance: energy conserved within 2 % without damping");
  // The error shrinks as the resolution grows.
  for (auto it = results.begin(); std::next(it) != results.end(); ++it) {
    const PlateResult& coarse = it->second;
    const PlateResult& fine = std::next(it)->second;
    summary.check_at_most(fmt::format("{} period error shrinks from H/dp={} to {}", tag, coarse.c.resolution, fine.c.resolution),
                          std::abs(fine.period_error) / std::abs(coarse.period_error), 1.0,
                          "convergence: the error must fall as the resolution grows");
  }
  Json row = {{"material", material}};
  std::vector<double> periods_on_ladder;
  for (const auto& [res, r] : results) {
    row[fmt::format("period_res{}", res)] = r.period;
    row[fmt::format("period_error_res{}", res)] = r.period_error;
    periods_on_ladder.push_back(r.period);
  }
  row["period_theory"] = finest.theory;
  if (periods_on_ladder.size() >= 3) {
    const std::size_t n = periods_on_ladder.size();
    if (const auto c = three_grid_convergence(periods_on_ladder[n - 3], periods_on_ladder[n - 2], periods_on_ladder[n - 1], 2.0))
      write_estimate(*c, row);
    const auto& errors_coarse = results.at(rungs[n - 2]).period_error;
    row["order_vs_theory"] = order_from_errors(std::abs(errors_coarse), std::abs(finest.period_error), 2.0);
  }
  return row;
}

// At V_f = 0.01 the strains are ~1e-3: both materials reduce to the same linear elasticity, so
// their periods must agree to O(strain) at equal resolution.
void check_materials_agree(std::map<std::string, std::map<int, PlateResult>>& by_material, SuiteSummary& summary) {
  for (const auto& [res, svk] : by_material["saint_venant_kirchhoff"]) {
    const auto it = by_material["neo_hookean"].find(res);
    if (it == by_material["neo_hookean"].end()) continue;
    summary.check_at_most(fmt::format("NH and SVK periods agree at small strain, H/dp={}", res),
                          std::abs(it->second.period / svk.period - 1.0), 0.005,
                          "both models linearise to S = lambda tr(E) I + 2 G E (paper Eqs. 10, 12-13)");
  }

}

// The paper's kernel correction B0 on the same ladder: the second-order weights must bend more
// accurately at every rung (gradient_weights.hpp).
void compare_with_b0(const SuiteContext& ctx, const std::map<int, PlateResult>& second_order, SuiteSummary& summary) {
  const double periods = periods_to_run(ctx);
  const std::vector<int> b0_rungs = ctx.quick ? std::vector<int>{4, 8} : std::vector<int>{4, 8, 16};
  Json b0_table = Json::object();
  for (int res : b0_rungs) {
    PlateCase c{"saint_venant_kirchhoff", res, 0.01, 0.3975, periods, "first_order"};
    const PlateResult b0 = run_case(ctx, c, summary);
    const PlateResult& second = second_order.at(res);
    b0_table[fmt::format("period_error_res{}", res)] = b0.period_error;
    summary.check_at_most(fmt::format("second-order weights bend more accurately than B0 at H/dp={} (|error| ratio)", res),
                          std::abs(second.period_error) / std::abs(b0.period_error), 1.0,
                          "the claim of gradient_weights.hpp; theory: Euler-Bernoulli period");
  }
  summary.extra()["paper_b0_weights"] = b0_table;

}

// Large deflection (tip amplitude over half the length) and a nearly incompressible plate.
void run_large_and_incompressible(const SuiteContext& ctx, SuiteSummary& summary) {
  const double periods = periods_to_run(ctx);
  const int res_extra = ctx.quick ? 8 : 16;
  for (const std::string& material : kMaterials) {
    if (ctx.quick && material == "saint_venant_kirchhoff") continue;
    const PlateResult large = run_case(ctx, {material, res_extra, 0.05, 0.3975, periods}, summary);
    const std::string tag = material == "neo_hookean" ? "NH" : "SVK";
    if (large.diverged) summary.check_missing(tag + " Vf=0.05 runs", "diverged", "issue 3: large-deflection case");
    else summary.check_at_most(tag + " Vf=0.05 energy drift", large.energy_drift, 0.02, "issue 3: energy within 2 %");
  }
  const PlateResult incompressible = run_case(ctx, {"saint_venant_kirchhoff", ctx.quick ? 4 : 8, 0.01, 0.49, periods}, summary);
  if (incompressible.diverged) summary.check_missing("nu=0.49 runs stably", "diverged", "issue 3 acceptance");
  else summary.check_at_most("nu=0.49 energy drift (stable with the solid time step)", incompressible.energy_drift, 0.02,
                             "issue 3 acceptance: a plate with nu = 0.49 runs stably");

}

}  // namespace

SuiteSummary run_oscillating_plate_suite(const SuiteContext& ctx) {
  SuiteSummary summary("oscillating-plate", ctx.quick, ctx.threads);
  Json table = Json::array();
  std::map<std::string, std::map<int, PlateResult>> by_material;
  for (const std::string& material : kMaterials) table.push_back(run_material_ladder(ctx, material, by_material[material], summary));
  summary.extra()["convergence"] = table;
  check_materials_agree(by_material, summary);
  compare_with_b0(ctx, by_material["saint_venant_kirchhoff"], summary);
  run_large_and_incompressible(ctx, summary);
  summary.write(ctx.out_dir);
  render_figures(ctx, "plot_oscillating_plate.py", summary);
  summary.write(ctx.out_dir);
  return summary;
}

}  // namespace mrsph::verification
