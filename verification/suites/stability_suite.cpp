// verify --suite stability: sweeps that look for where each method fails. Each run is a data point
// (completed, diverged at time t in body b for reason r, or too slow for its wall-clock budget);
// a divergence never stops the sweep. Families:
//   coupling    FSI2 (case III): solid kinematics averaged / averaged (code's second difference) /
//               instantaneous x Kelvin-Voigt damping 0 / 0.05 x multi-step position Verlet /
//               single step / multi-step velocity Verlet
//   time steps  FSI2: acoustic CFL factor above the criterion's 0.6, advection CFL above 0.25;
//               gate: solid CFL factor
//   poisson     gate: nu up to 0.499, multiple and single time steps
//   ratio       FSI2: resolution ratio dp_F/dp_S = 1-4 at bh/dp_S = 4 and 8
// Output: stability_map.csv (one row per run), the map as a figure, and the tables in summary.json.
#include "suites/stability_suite.hpp"

#include "io/csv_table.hpp"
#include "sweep/sweep.hpp"
#include "suites/scene_run.hpp"

#include <fmt/format.h>

namespace mrsph::verification {

namespace {

std::vector<SweepRun> coupling_family(bool quick) {
  std::vector<SweepRun> runs;
  const double end = quick ? 10.0 : 20.0;
  const std::vector<std::string> schedules =
      quick ? std::vector<std::string>{"multi_step_position_verlet"}
            : std::vector<std::string>{"multi_step_position_verlet", "single_step_position_verlet", "multi_step_velocity_verlet"};
  for (const std::string& schedule : schedules)
    for (const std::string kinematics : {"averaged", "averaged_second_difference", "instantaneous"})
      for (const double damping : {0.0, 0.05}) {
        SweepRun r;
        r.label = fmt::format("coupling: {}, {}, damping {:g}", schedule, kinematics, damping);
        r.scene = "turek_hron_fsi2.json";
        r.overrides = {fmt::format("schedule.type=\"{}\"", schedule), fmt::format("schedule.solid_kinematics=\"{}\"", kinematics),
                       fmt::format("parameters.damping={}", damping)};
        r.end_time = end;
        r.wall_limit_s = quick ? 60.0 : 300.0;
        r.config = {{"family", "coupling"}, {"schedule", schedule}, {"solid_kinematics", kinematics}, {"damping", damping}};
        runs.push_back(r);
      }
  return runs;
}

// One run of the time-step family: `scene` with the CFL factor at scene path `key` set to `cfl`;
// `factor` names it in the run's config ("acoustic_cfl", "advection_cfl", "solid_cfl") and label.
SweepRun time_step_run(const std::string& case_name, const std::string& scene, const std::string& factor,
                       const std::string& key, double cfl, double end_time) {
  SweepRun r;
  r.label = fmt::format("time step: {} {} CFL {:g}", case_name, factor.substr(0, factor.rfind("_cfl")), cfl);
  r.scene = scene;
  r.overrides = {fmt::format("{}={}", key, cfl)};
  r.end_time = end_time;
  r.wall_limit_s = 300.0;
  r.config = {{"family", "time steps"}, {"case", case_name}, {"factor", factor}, {"value", cfl}};
  return r;
}

std::vector<SweepRun> time_step_family(bool quick) {
  std::vector<SweepRun> runs;
  const double fsi2_end = quick ? 5.0 : 20.0, gate_end = quick ? 0.05 : 0.2;
  const std::vector<double> acoustic = quick ? std::vector<double>{0.6, 1.2} : std::vector<double>{0.6, 0.8, 1.0, 1.2, 1.6, 2.0};
  for (const double cfl : acoustic)
    runs.push_back(time_step_run("FSI2", "turek_hron_fsi2.json", "acoustic_cfl", "fluid.acoustic_cfl", cfl, fsi2_end));
  // The advection step bounds how far a particle moves between neighbour-list builds. The paper's
  // full acoustic steps pass it by up to one acoustic step: 0.25 h becomes up to 0.36 h at FSI2's
  // Mach 0.22 (performance.md section 13), so the sweep goes beyond that.
  const std::vector<double> advection = quick ? std::vector<double>{0.5} : std::vector<double>{0.25, 0.35, 0.5, 0.7, 1.0};
  for (const double cfl : advection)
    runs.push_back(time_step_run("FSI2", "turek_hron_fsi2.json", "advection_cfl", "fluid.advection_cfl", cfl, fsi2_end));
  const std::vector<double> solid = quick ? std::vector<double>{0.6, 1.5} : std::vector<double>{0.6, 0.9, 1.2, 1.5, 2.0, 3.0};
  for (const double cfl : solid)
    runs.push_back(time_step_run("gate", "elastic_gate.json", "solid_cfl", "solids[0].cfl", cfl, gate_end));
  return runs;
}

std::vector<SweepRun> poisson_family(bool quick) {
  std::vector<SweepRun> runs;
  const std::vector<double> nus = quick ? std::vector<double>{0.47, 0.499} : std::vector<double>{0.3, 0.4, 0.45, 0.47, 0.49, 0.495, 0.499};
  for (const std::string schedule : {"multi_step_position_verlet", "single_step_position_verlet"})
    for (const double nu : nus) {
      if (quick && schedule == "single_step_position_verlet") continue;
      SweepRun r;
      r.label = fmt::format("poisson: gate nu {:g}, {}", nu, schedule);
      r.scene = "elastic_gate.json";
      r.overrides = {fmt::format("parameters.nu={}", nu), fmt::format("schedule.type=\"{}\"", schedule)};
      r.end_time = quick ? 0.05 : 0.2;
      r.wall_limit_s = quick ? 60.0 : 240.0;
      r.config = {{"family", "poisson"}, {"poisson_ratio", nu}, {"schedule", schedule}};
      runs.push_back(r);
    }
  return runs;
}

std::vector<SweepRun> ratio_family(bool quick) {
  std::vector<SweepRun> runs;
  const std::vector<std::pair<int, int>> pairs =
      quick ? std::vector<std::pair<int, int>>{{4, 2}, {4, 3}}
            : std::vector<std::pair<int, int>>{{4, 1}, {4, 2}, {4, 3}, {4, 4}, {8, 2}, {8, 3}, {8, 4}};
  for (const auto& [res, ratio] : pairs) {
    SweepRun r;
    r.label = fmt::format("ratio: FSI2 bh/dp_S {} ratio {}", res, ratio);
    r.scene = "turek_hron_fsi2.json";
    r.overrides = {fmt::format("parameters.resolution={}", res), fmt::format("parameters.ratio={}", ratio)};
    // The periodic channel (13 long) must be a whole number of fluid spacings (the loader refuses it
    // otherwise): at ratio 3 (dp_F = 0.15 or 0.075) the outlet end moves from 11 to 11.05.
    if (ratio == 3) r.overrides.push_back("parameters.channel_end=11.05");
    r.end_time = quick ? 5.0 : 20.0;
    r.wall_limit_s = 600.0;
    r.config = {{"family", "ratio"}, {"resolution", res}, {"ratio", ratio}};
    runs.push_back(r);
  }
  return runs;
}

}  // namespace

SuiteSummary run_stability_suite(const SuiteContext& ctx) {
  SuiteSummary summary("stability", ctx.quick, ctx.threads);
  std::vector<SweepRun> runs;
  for (auto family : {coupling_family, time_step_family, poisson_family, ratio_family})
    for (SweepRun& r : family(ctx.quick)) runs.push_back(std::move(r));
  const std::vector<SweepOutcome> outcomes = sweep(ctx, runs, summary);
  if (outcomes.empty()) {
    summary.write(ctx.out_dir);
    return summary;
  }

  CsvTable map;
  map.columns = {"index", "completed", "diverged", "timed_out", "divergence_time", "wall_s", "max_mach"};
  Json table = Json::array();
  for (std::size_t k = 0; k < outcomes.size(); ++k) {
    const SweepOutcome& o = outcomes[k];
    const Json record = outcome_record(o);
    const double t_div = o.diverged && o.divergence.is_object() ? o.divergence.value("time", double(NAN)) : NAN;
    // The largest Mach number: a run can complete and still leave the weakly compressible regime.
    const double mach = o.compressibility.is_object() && o.compressibility.contains("max_mach")
                            ? o.compressibility["max_mach"].value("value", double(NAN)) : NAN;
    map.add_row({double(k), double(o.completed), double(o.diverged), double(o.timed_out), t_div,
                 o.cost.value("wall_s", double(NAN)), mach});
    Json row = {{"index", k}, {"label", o.run.label}, {"config", o.run.config}, {"end_time", o.run.end_time}};
    row.update(record);
    row["wall_s"] = o.cost.value("wall_s", Json());
    table.push_back(row);
    SuiteRun run;
    run.case_name = o.run.label;
    run.config = o.run.config;
    run.metrics = record;
    run.metrics["completed_flag"] = o.completed ? 1.0 : 0.0;  // numeric, for the regression baseline
    run.cost = o.cost;
    run.compressibility = o.compressibility;
    run.diverged = o.diverged;
    run.divergence = o.divergence;
    summary.add_run(std::move(run));
  }
  map.write(ctx.out_dir / "stability_map.csv");
  summary.extra()["map"] = table;

  // The configurations the scenes ship with must be stable; everything else is mapped, not judged.
  for (const SweepOutcome& o : outcomes) {
    const Json& c = o.run.config;
    const bool shipped =
        (c["family"] == "coupling" && c["schedule"] == "multi_step_position_verlet" && c["solid_kinematics"] == "averaged" &&
         c["damping"].get<double>() == 0.05) ||
        (c["family"] == "time steps" && c["value"].get<double>() == (c["factor"] == "advection_cfl" ? 0.25 : 0.6)) ||
        (c["family"] == "poisson" && c["poisson_ratio"].get<double>() == 0.47 && c["schedule"] == "multi_step_position_verlet") ||
        (c["family"] == "ratio" && c["resolution"].get<int>() == 4 && c["ratio"].get<int>() == 2);
    if (!shipped) continue;
    if (o.completed) summary.check_range(o.run.label + ": completes", 1.0, 1.0, 1.0, "the scenes' own configuration");
    else summary.check_missing(o.run.label + ": completes", outcome_record(o).dump(), "the scenes' own configuration");
  }
  summary.write(ctx.out_dir);
  render_figures(ctx, "plot_stability.py", summary);
  summary.write(ctx.out_dir);
  return summary;
}

}  // namespace mrsph::verification
