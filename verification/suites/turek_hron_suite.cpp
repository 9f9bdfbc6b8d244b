// verify --suite turek-hron: the FSI2 beam behind a cylinder (CASES.md section 1), the paper's
// cases I-IV (and V: the finer beam of case II at case III's fluid resolution, ratio 4).
//   tip metrics (from the displacement of the beam's free-end centre S, after the settling time):
//     amplitude_y = mean half peak-to-peak of y per cycle (A_y / D with D = 1), strouhal = f_y D/U0,
//     mean_x, amplitude_x, frequency_x / frequency_y (the 2:1 Lissajous figure), mean_y;
//     drag and lift on cylinder + beam (mean, half peak-to-peak).
//   cost: wall and CPU time, particles per body, advection / acoustic / solid steps.
// Full mode: t = 200, statistics over t >= 100 (as the paper's code's runs here). Quick mode:
// case III to t = 70: the self-excited oscillation must grow and oscillate at the published St.
#include "suites/turek_hron_suite.hpp"

#include "io/csv_table.hpp"
#include "metrics/signal_metrics.hpp"
#include "report/reference_table.hpp"
#include "suites/scene_run.hpp"
#include "sweep/sweep.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <optional>

namespace mrsph::verification {

namespace {

struct FsiResult {
  FsiCase c;
  bool diverged = false;
  double wall_s = NAN;
  Json metrics = Json::object();
};

}  // namespace

Json fsi2_metrics(const ObserverSeries& tip, const ObserverSeries& forces, double end_time, double settle) {
  const std::vector<double> x = series_column(tip, 0), y = series_column(tip, 1);
  Json m = Json::object();
  if (const auto sy = oscillation_stats(tip.time, y, settle)) {
    m["amplitude_y"] = sy->amplitude;
    m["amplitude_y_spread"] = sy->amplitude_spread;
    m["strouhal"] = sy->frequency;  // D = U0 = 1
    m["strouhal_spread"] = sy->frequency_spread;
    m["mean_y"] = sy->mean;
    m["cycles"] = sy->cycles;
    if (const auto f = spectral_peak_frequency(tip.time, y, settle, 0.05, 1.0)) m["strouhal_spectral"] = *f;
  }
  if (const auto sx = oscillation_stats(tip.time, x, settle)) {
    m["mean_x"] = sx->mean;
    m["amplitude_x"] = sx->amplitude;
    m["frequency_x"] = sx->frequency;
    if (m.contains("strouhal")) m["frequency_ratio_x_to_y"] = sx->frequency / m["strouhal"].get<double>();
  }
  // Forces carry SPH pressure noise: smoothed over 0.5 D/U0 (a tenth of the lift period) first,
  // which lowers the lift amplitude by sinc(pi f w) = 1.6 % and the drag amplitude by 6 %.
  const double window = 0.5;
  if (const auto drag = oscillation_stats(forces.time, moving_average(forces.time, series_column(forces, 0), window), settle)) {
    m["drag_mean"] = drag->mean;
    m["drag_amplitude"] = drag->amplitude;
  }
  if (const auto lift = oscillation_stats(forces.time, moving_average(forces.time, series_column(forces, 1), window), settle)) {
    m["lift_mean"] = lift->mean;
    m["lift_amplitude"] = lift->amplitude;
  }
  // Growth of the self-excited oscillation: half peak-to-peak of y over the last 10 time units.
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t k = 0; k < y.size(); ++k)
    if (tip.time[k] >= end_time - 10.0) { lo = std::min(lo, y[k]); hi = std::max(hi, y[k]); }
  m["amplitude_y_last_10"] = 0.5 * (hi - lo);

  return m;
}

SweepRun fsi2_sweep_run(const FsiCase& c, double end_time) {
  SweepRun r;
  r.label = fmt::format("FSI2 case {} (ratio {}, bh/dp_S = {}, {})", c.name, c.ratio, c.resolution, c.schedule);
  r.scene = "turek_hron_fsi2.json";
  r.overrides = {fmt::format("parameters.ratio={}", c.ratio), fmt::format("parameters.resolution={}", c.resolution),
                 fmt::format("schedule.type=\"{}\"", c.schedule)};
  if (c.sound_speed_factor != 10) {
    r.label += fmt::format(", c = {} U0", c.sound_speed_factor);
    r.overrides.push_back(fmt::format("parameters.sound_speed={} * U0", c.sound_speed_factor));
  }
  if (c.fluid_h_over_dp) {
    r.label += fmt::format(", h = {:g} dp_F", *c.fluid_h_over_dp);
    r.overrides.push_back(fmt::format("fluid.h_over_dp={:g}", *c.fluid_h_over_dp));
  }
  r.end_time = end_time;
  r.config = {{"case", c.name}, {"ratio", c.ratio}, {"resolution", c.resolution}, {"schedule", c.schedule},
              {"sound_speed_factor", c.sound_speed_factor}};
  if (c.fluid_h_over_dp) r.config["fluid_h_over_dp"] = *c.fluid_h_over_dp;
  return r;
}

namespace {

// What a case's run left, whether it ran here (in-process, ctx.threads) or came from the sweep cache.
struct CaseRun {
  std::vector<ObserverSeries> series;
  Json cost = Json::object();
  Json divergence;  // null unless diverged
  Json parameters = Json::object();
  bool reused = false;
  std::string failure;  // no outputs (with --merge: not run, or not finished, yet); nothing else is set
  Json compressibility;  // null if unknown
};

CaseRun run_here(const SuiteContext& ctx, const FsiCase& c, double end_time) {
  if (ctx.log) ctx.log(fmt::format("turek-hron: case {} (ratio {}, bh/dp_S = {}, {}, t = {:g})", c.name, c.ratio,
                                   c.resolution, c.schedule, end_time));
  const SweepRun as_sweep = fsi2_sweep_run(c, end_time);
  SceneRun run = run_scene(ctx, as_sweep.scene, as_sweep.overrides, [&](const LoadedScene&) {
    RunOptions options;
    options.end_time = end_time;
    return options;
  });
  // Shared with the sweep suites (speed-accuracy reuses the cases).
  persist_in_cache(ctx, as_sweep, run.scene, run.result);
  CaseRun out{run.result.series, cost_json(run), divergence_record(run), Json::object(), false, "", compressibility_record(run)};
  for (const char* name : {"dp_solid", "dp_fluid", "damping"}) out.parameters[name] = run.scene.parameters.at(name);
  return out;
}

CaseRun from_sweep(const SweepOutcome& o) {
  if (!o.failure.empty()) return CaseRun{{}, Json::object(), Json(), Json::object(), false, o.failure, Json()};
  return CaseRun{o.series, o.cost, o.diverged ? o.divergence : Json(), o.parameters, o.reused, "", o.compressibility};
}

FsiResult analyse_case(const SuiteContext& ctx, const FsiCase& c, const CaseRun& run, double end_time, double settle,
                       SuiteSummary& summary) {
  FsiResult out{c};
  out.diverged = !run.divergence.is_null();
  out.wall_s = run.cost.value("wall_s", double(NAN));
  write_observer_series(run.series, ctx.out_dir / ("case_" + c.name));
  out.metrics = fsi2_metrics(series_named(run.series, "tip"), series_named(run.series, "forces"), end_time, settle);

  SuiteRun record;
  record.case_name = c.name;
  record.config = {{"ratio", c.ratio}, {"resolution", c.resolution}, {"schedule", c.schedule},
                   {"dp_solid", run.parameters.at("dp_solid")}, {"dp_fluid", run.parameters.at("dp_fluid")},
                   {"end_time", end_time}, {"settle_time", settle}, {"scene", "turek_hron_fsi2.json"},
                   {"solid_damping", run.parameters.at("damping")}, {"reused_from_cache", run.reused}};
  record.metrics = out.metrics;
  record.cost = run.cost;
  record.compressibility = run.compressibility;
  record.diverged = out.diverged;
  record.divergence = run.divergence;
  summary.add_run(std::move(record));
  return out;
}

double metric(const FsiResult& r, const char* name) {
  return r.metrics.contains(name) ? r.metrics[name].get<double>() : NAN;
}

// The paper's code's tip curve, measured here (for the figure), if the reference directory has it.
void copy_peer_curve(const SuiteContext& ctx, SuiteSummary& summary) {
  if (!ctx.reference_dir) {
    summary.note_skipped("the paper's code's tip curve", "no --reference-dir given");
    return;
  }
  const auto path = *ctx.reference_dir / "sphinxsys" / "runs-here" / "fsi2_BeamObserver_Position_everystep.dat";
  const auto table = read_numeric_table(path);
  if (!table || table->columns.size() < 3) {
    summary.note_skipped("the paper's code's tip curve", path.string() + " is missing");
    return;
  }
  CsvTable peer;
  peer.columns = {"time", "dx", "dy"};
  const double x0 = table->columns[1].front(), y0 = table->columns[2].front();
  for (std::size_t k = 0; k < table->columns[0].size(); ++k)
    peer.add_row({table->columns[0][k], table->columns[1][k] - x0, table->columns[2][k] - y0});
  peer.write(ctx.out_dir / "peer_sphinxsys_tip.csv");
}

std::vector<FsiCase> fsi2_cases(const SuiteContext& ctx) {
  if (ctx.quick) return {{"III", 2, 4, "multi_step_position_verlet"}};
  return {{"I", 1, 4, "multi_step_position_verlet"},
          {"II", 1, 8, "multi_step_position_verlet"},
          {"III", 2, 4, "multi_step_position_verlet"},
          {"IV", 2, 4, "single_step_position_verlet"},
          {"V", 4, 8, "multi_step_position_verlet"},
          {"III-c20", 2, 4, "multi_step_position_verlet", 20},
          {"III-c40", 2, 4, "multi_step_position_verlet", 40},
          {"III-h2", 2, 4, "multi_step_position_verlet", 10, 2.0}};
}

// One case at a time in-process (ctx.threads each; always so for the single quick case, and with
// --jobs 1), or else through the sweep engine: single-threaded runs, --jobs at once, reused from the
// cache when done, or emitted as commands (--emit-commands) and analysed later (--merge). Nothing
// when the commands were only emitted.
std::optional<std::vector<CaseRun>> run_cases(const SuiteContext& ctx, const std::vector<FsiCase>& cases, double end_time,
                                              bool in_process, SuiteSummary& summary) {
  std::vector<CaseRun> runs;
  if (in_process) {
    for (const FsiCase& c : cases) runs.push_back(run_here(ctx, c, end_time));
    return runs;
  }
  std::vector<SweepRun> sweep_runs;
  for (const FsiCase& c : cases) sweep_runs.push_back(fsi2_sweep_run(c, end_time));
  const auto outcomes = sweep(ctx, sweep_runs, summary);
  if (outcomes.empty()) return std::nullopt;
  for (const SweepOutcome& o : outcomes) runs.push_back(from_sweep(o));
  return runs;
}

// Case III's answer must not depend on the artificial sound speed c, a numerical parameter: with the
// tolerances of issue 17 for CFD2's drag (c = 20 and 40 U0 within 2 % of each other, 10 U0 within 5 %
// of 40), on the amplitude and on St (turek-hron.md: the amplitude rises by 8 % from 10 to 40 U0).
void check_sound_speed_independence(const std::map<std::string, FsiResult>& results, SuiteSummary& summary) {
  if (!results.count("III-c20") || !results.count("III-c40")) return;  // said where the runs are missing
  const std::string source = "issue 17: independence of c in the incompressible limit (CFD2's tolerances)";
  const FsiResult &c10 = results.at("III"), &c20 = results.at("III-c20"), &c40 = results.at("III-c40");
  for (const char* m : {"amplitude_y", "strouhal"}) {
    const double at40 = metric(c40, m);
    summary.check_at_most(fmt::format("case III {}: |c = 20 U0 / c = 40 U0 - 1|", m), std::abs(metric(c20, m) / at40 - 1.0),
                          0.02, source);
    summary.check_at_most(fmt::format("case III {}: |c = 10 U0 / c = 40 U0 - 1|", m), std::abs(metric(c10, m) / at40 - 1.0),
                          0.05, source);
  }
}

// Nor on the fluid's kernel width, another numerical parameter: at h = 2.0 dp_F instead of 1.3 the
// beam's amplitude within 3 % (the precision issue 17 asks of A_y/D against Turek & Hron; the cycles'
// spread is 2.3 %) and St within 2 % (issue 17's precision for CFD3's St). Measured: 0.4 % and 0.0 %,
// where the cylinders' drag at one D/dp moves by 2-8 % with h (reports/pressure.md section 33).
void check_kernel_width_independence(const std::map<std::string, FsiResult>& results, SuiteSummary& summary) {
  if (!results.count("III-h2")) return;  // said where the run is missing
  const std::string source = "issue 17: independence of a numerical parameter; pressure.md section 33";
  const FsiResult &paper = results.at("III"), &wide = results.at("III-h2");
  const std::map<std::string, double> tolerance{{"amplitude_y", 0.03}, {"strouhal", 0.02}};
  for (const auto& [m, tol] : tolerance)
    summary.check_at_most(fmt::format("case III {}: |h = 2.0 dp_F / h = 1.3 dp_F - 1|", m),
                          std::abs(metric(wide, m.c_str()) / metric(paper, m.c_str()) - 1.0), tol, source);
}

// Case III against the published range (quick: while the oscillation grows), the multiple steps'
// speed-up and case III's wall time.
void check_case_iii(const SuiteContext& ctx, const std::map<std::string, FsiResult>& results, bool in_process,
                    const Json& refs, SuiteSummary& summary) {
  const Json& range = refs["published_range"];
  const std::string range_source = range["source"];
  const FsiResult& III = results.at("III");
  if (III.diverged) {
    summary.check_missing("case III runs to the end", "diverged", "issue 4");
  } else if (ctx.quick) {
    // The frequency is set while the oscillation grows; the amplitude saturates at about t = 60. (It
    // did at t = 50 while the periodic seam's start-up blast kicked the beam; the channel drive of
    // boundary/inflow.hpp removed the blast, and the growth starts from a smaller seed: stability.md.)
    summary.check_range("case III strouhal (t = 40-70)", metric(III, "strouhal"), range["strouhal"][0],
                        range["strouhal"][1], range_source);
    summary.check_range("case III oscillation has grown: half peak-to-peak of y over t = 60-70",
                        metric(III, "amplitude_y_last_10"), 0.6, 1.0,
                        "the self-excited oscillation reaches about 0.8 D by t = 60 (paper Fig. 5, Turek & Hron)");
  } else {
    summary.check_range("case III amplitude_y (A_y/D)", metric(III, "amplitude_y"), range["amplitude_y"][0],
                        range["amplitude_y"][1], range_source);
    summary.check_range("case III strouhal", metric(III, "strouhal"), range["strouhal"][0], range["strouhal"][1], range_source);
    summary.check_range("case III x:y frequency ratio (Lissajous 2:1)", metric(III, "frequency_ratio_x_to_y"), 1.95, 2.05,
                        "paper section 4.1 and Bhardwaj & Mittal 2012: a 2:1 Lissajous figure");
    if (results.count("IV"))
      summary.check_range("speed-up of multiple over single time steps (wall IV / wall III)",
                          results.at("IV").wall_s / III.wall_s, 1.0, 1e9,
                          "issue 4: multiple steps beat the single step by a measured factor (paper: 1.8)");
    check_sound_speed_independence(results, summary);
    check_kernel_width_independence(results, summary);
    if (in_process && ctx.threads == 2)
      summary.check_at_most("case III wall time to t = 200 on 2 threads [s]", III.wall_s, 60.0,
                            "issue 4 acceptance; the paper's code takes about 100 s here (runs-here)");
    else
      summary.note_skipped("case III wall-time check", "needs --threads 2 --jobs 1 (the acceptance is stated for one run on 2 threads)");
  }

}

// The cases beside the paper's Table 2, the speed-ups, the references.
void add_tables(const std::map<std::string, FsiResult>& results, const Json& refs, SuiteSummary& summary) {
  const FsiResult& III = results.at("III");
  // Table of cases beside the paper's Table 2 and the references.
  Json table = Json::array();
  const Json& paper = refs["paper_table_2"]["cases"];
  for (const auto& [name, r] : results) {
    Json row = {{"case", name}, {"ratio", r.c.ratio}, {"resolution", r.c.resolution}, {"schedule", r.c.schedule},
                {"amplitude_y", metric(r, "amplitude_y")}, {"strouhal", metric(r, "strouhal")},
                {"mean_x", metric(r, "mean_x")}, {"amplitude_x", metric(r, "amplitude_x")}, {"wall_s", r.wall_s},
                {"diverged", r.diverged}};
    if (paper.contains(name))
      row["paper"] = {{"amplitude_y", paper[name]["amplitude_y"]}, {"strouhal", paper[name]["strouhal"]},
                      {"cpu_s", paper[name]["cpu_s"]}, {"particles", paper[name]["particles"]}};
    table.push_back(row);
  }
  summary.extra()["table"] = table;
  Json speedups = Json::object();
  if (results.count("I")) speedups["III_vs_I"] = results.at("I").wall_s / III.wall_s;
  if (results.count("IV")) speedups["III_vs_IV"] = results.at("IV").wall_s / III.wall_s;
  speedups["paper_III_vs_I"] = paper["I"]["cpu_s"].get<double>() / paper["III"]["cpu_s"].get<double>();
  speedups["paper_III_vs_IV"] = paper["IV"]["cpu_s"].get<double>() / paper["III"]["cpu_s"].get<double>();
  summary.extra()["speedups"] = speedups;
  summary.extra()["references"] = {{"turek_hron", refs["turek_hron_2006"]}, {"paper_code_here", refs["paper_code_here"]},
                                   {"paper_table_3", refs["paper_table_3"]}};
}

}  // namespace

SuiteSummary run_turek_hron_suite(const SuiteContext& ctx) {
  SuiteSummary summary("turek-hron", ctx.quick, ctx.threads);
  const Json refs = read_project_reference(ctx.project_dir, "turek_hron_fsi2.json");
  const std::vector<FsiCase> cases = fsi2_cases(ctx);
  const double end_time = ctx.quick ? 70.0 : 200.0;
  const double settle = ctx.quick ? 40.0 : 100.0;
  const bool in_process = (ctx.jobs == 1 || cases.size() == 1) && ctx.sweep_mode == SweepMode::Run;
  const auto runs = run_cases(ctx, cases, end_time, in_process, summary);
  if (!runs) {  // commands emitted
    summary.write(ctx.out_dir);
    return summary;
  }
  std::map<std::string, FsiResult> results;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    if ((*runs)[k].failure.empty())
      results.emplace(cases[k].name, analyse_case(ctx, cases[k], (*runs)[k], end_time, settle, summary));
    else if (ctx.sweep_mode == SweepMode::Merge)  // not run yet: said, not failed
      summary.note_skipped("case " + cases[k].name, (*runs)[k].failure + " (run its command first)");
    else
      summary.check_missing("case " + cases[k].name + " runs", (*runs)[k].failure, "issue 4");
  }
  if (!results.count("III")) {
    summary.check_missing("case III runs to the end", "no run", "issue 4");
    summary.write(ctx.out_dir);
    return summary;
  }
  check_case_iii(ctx, results, in_process, refs, summary);
  add_tables(results, refs, summary);
  copy_peer_curve(ctx, summary);
  summary.write(ctx.out_dir);
  render_figures(ctx, "plot_turek_hron.py", summary);
  summary.write(ctx.out_dir);
  return summary;
}

}  // namespace mrsph::verification
