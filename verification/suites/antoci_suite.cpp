// verify --suite antoci: dam break through an elastic gate (Antoci et al. 2007; CASES.md section 2),
// the paper's cases I-IV, against the experiment.
//   displacement of the gate's free end (positive downstream, i.e. towards -x here, and upward),
//   in mm, compared at the experiment's times (Ex10X / Ex10Y, first sample subtracted: a
//   digitisation offset, PROVENANCE.md): RMS and max error, the peak and its time.
//   Antoci's SPH, Yang et al.'s SPH-FEM and the paper's code run here are drawn for comparison.
//   Snapshots of case III at t = 0.04, 0.08, ..., 0.32 s (VTP and a CSV for the figure panel).
//   A dry-bed dam break (Martin & Moyce 1952) is run as a free-surface sanity scene.
#include "suites/antoci_suite.hpp"

#include "io/csv_table.hpp"
#include "metrics/signal_metrics.hpp"
#include "report/reference_table.hpp"
#include "suites/gate_experiment.hpp"
#include "suites/scene_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace mrsph::verification {

namespace {

struct GateCase {
  std::string name;
  int ratio;
  int resolution;
  std::string schedule;
  std::string gradient_correction = "second_order";
  std::optional<double> damping{};  // Kelvin-Voigt coefficient; the scene's (0.1) if not given
  std::string kinematics{};       // solid velocity/acceleration the fluid sees; the scene's if empty
  std::optional<double> fluid_h_over_dp{};  // the fluid's smoothing length h / dp_F; the scene's (1.3) if not given
};

// The largest value of a curve and when it occurs (the experiment's peak, computed from its curve).
struct Peak {
  double value = NAN, time = NAN;
};
Peak peak_of(const std::optional<Curve>& c) {
  Peak p;
  if (!c) return p;
  for (std::size_t k = 0; k < c->t.size(); ++k)
    if (!(c->value[k] <= p.value)) p = {c->value[k], c->t[k]};
  return p;
}

struct GateResult {
  GateCase c;
  bool diverged = false;
  double wall_s = NAN;
  Curve x, y;  // mm
  Json metrics = Json::object();
  SuiteRun record;  // for the summary; the caller adds it (cases may run concurrently)
};

std::vector<std::string> case_overrides(const GateCase& c) {
  std::vector<std::string> overrides{fmt::format("parameters.ratio={}", c.ratio),
                                     fmt::format("parameters.resolution={}", c.resolution),
                                     fmt::format("schedule.type=\"{}\"", c.schedule),
                                     fmt::format("solids[0].gradient_correction=\"{}\"", c.gradient_correction)};
  if (c.damping) overrides.push_back(fmt::format("parameters.damping={}", *c.damping));
  if (!c.kinematics.empty()) overrides.push_back(fmt::format("schedule.solid_kinematics=\"{}\"", c.kinematics));
  if (c.fluid_h_over_dp) overrides.push_back(fmt::format("fluid.h_over_dp={:g}", *c.fluid_h_over_dp));
  return overrides;
}

// The case's run; with `snapshots`, VTP snapshots and every particle at t = 0.04, 0.08, ..., 0.32 s
// into `frames` (the figure's panels).
SceneRun simulate_case(const SuiteContext& ctx, const GateCase& c, bool snapshots, CsvTable& frames) {
  frames.columns = {"time", "body", "x", "y", "pressure"};
  return run_scene(ctx, "elastic_gate.json", case_overrides(c), [&](const LoadedScene&) {
    RunOptions options;
    if (snapshots) {
      options.snapshot_interval = 0.04;
      options.snapshot_dir = ctx.out_dir / ("case_" + c.name) / "snapshots";
      for (int k = 1; k <= 8; ++k) options.sample_times.push_back(0.04 * k);
      options.on_sample = [&](const Simulation& sim) {
        const FluidParticles& f = sim.fluid().particles;
        for (std::size_t i = 0; i < f.size(); ++i) frames.add_row({sim.time, 0.0, f.pos[i].x(), f.pos[i].y(), f.p[i]});
        for (const SolidBody& s : sim.solids())
          for (const Vec2& p : s.particles.pos) frames.add_row({sim.time, 1.0, p.x(), p.y(), 0.0});
      };
    }
    return options;
  });
}

// The free end's noise, and its curves against the experiment's (RMS, max, peak; the loading phase).
void measure_against_experiment(const GateResult& out, const std::optional<Curve>& exp_x, const std::optional<Curve>& exp_y,
                                Json& m) {
  if (!out.diverged && out.x.t.size() > 20) {
    // Particle-scale noise of the free end: the RMS of x about its 11 ms centred moving average
    // (the gate's first bending period is about 90 ms, so the average keeps the physical motion).
    const std::vector<double> smooth = moving_average(out.x.t, out.x.value, 0.011);
    double sum = 0.0;
    for (std::size_t k = 0; k < smooth.size(); ++k) sum += (out.x.value[k] - smooth[k]) * (out.x.value[k] - smooth[k]);
    m["tip_noise_x_mm"] = std::sqrt(sum / smooth.size());
  }
  if (exp_x && !out.diverged)
    if (const auto cx = compare_curves(out.x.t, out.x.value, exp_x->t, exp_x->value)) {
      m["rms_error_x_mm"] = cx->rms_error;
      m["max_error_x_mm"] = cx->max_error;
      m["peak_x_mm"] = cx->peak_value;
      m["peak_time_s"] = cx->peak_time;
      m["experiment_points"] = cx->points;
    }
  if (exp_x && !out.diverged) {
    // The loading phase (up to the experiment's frame at 0.12 s), where the gate's response is set
    // by the water pressure and its stiffness.
    Curve loading;
    for (std::size_t k = 0; k < exp_x->t.size(); ++k)
      if (exp_x->t[k] <= 0.125) { loading.t.push_back(exp_x->t[k]); loading.value.push_back(exp_x->value[k]); }
    if (const auto cl = compare_curves(out.x.t, out.x.value, loading.t, loading.value)) m["rms_error_x_loading_mm"] = cl->rms_error;
  }
  if (exp_y && !out.diverged)
    if (const auto cy = compare_curves(out.y.t, out.y.value, exp_y->t, exp_y->value)) {
      m["rms_error_y_mm"] = cy->rms_error;
      m["max_error_y_mm"] = cy->max_error;
      m["peak_y_mm"] = cy->peak_value;
    }
  if (!m.contains("peak_x_mm") && !out.x.value.empty()) {  // without the experiment: the run's own peak
    const auto it = std::max_element(out.x.value.begin(), out.x.value.end());
    m["peak_x_mm"] = *it;
    m["peak_time_s"] = out.x.t[static_cast<std::size_t>(it - out.x.value.begin())];
  }

}

GateResult run_case(const SuiteContext& ctx, const GateCase& c, const std::optional<Curve>& exp_x,
                    const std::optional<Curve>& exp_y, bool snapshots) {
  if (ctx.log) ctx.log(fmt::format("antoci: case {} (ratio {}, b/dp_S = {}, {})", c.name, c.ratio, c.resolution, c.schedule));
  CsvTable frames;
  const SceneRun run = simulate_case(ctx, c, snapshots, frames);
  GateResult out;
  out.c = c;
  out.diverged = run.result.divergence.has_value();
  out.wall_s = run.result.wall_s;
  write_observer_series(run.result.series, ctx.out_dir / ("case_" + c.name));
  if (snapshots) frames.write(ctx.out_dir / ("case_" + c.name) / "frames.csv");

  const ObserverSeries& tip = run.result.series.at(0);
  out.x = gate_tip_x_mm(tip);
  out.y.t = tip.time;
  for (const auto& row : tip.values) out.y.value.push_back(1000.0 * row[1]);
  measure_against_experiment(out, exp_x, exp_y, out.metrics);

  SuiteRun& record = out.record;
  record.case_name = c.name;
  record.config = {{"ratio", c.ratio}, {"resolution", c.resolution}, {"schedule", c.schedule},
                   {"gradient_correction", c.gradient_correction},
                   {"dp_solid", run.scene.parameters.at("dp_solid")}, {"dp_fluid", run.scene.parameters.at("dp_fluid")},
                   {"solid_damping", run.scene.parameters.at("damping")},
                   {"solid_kinematics", c.kinematics.empty() ? "averaged" : c.kinematics}, {"scene", "elastic_gate.json"}};
  record.metrics = out.metrics;
  record.cost = cost_json(run);
  record.compressibility = compressibility_record(run);
  record.diverged = out.diverged;
  record.divergence = divergence_record(run);
  return out;
}

double metric(const GateResult& r, const char* name) {
  return r.metrics.contains(name) ? r.metrics[name].get<double>() : NAN;
}

void write_curve(const Curve& x, const Curve& y, const std::filesystem::path& path) {
  CsvTable t;
  t.columns = {"time", "x_mm", "y_mm"};
  for (std::size_t k = 0; k < x.t.size(); ++k) t.add_row({x.t[k], x.value[k], interpolate(y.t, y.value, x.t[k])});
  t.write(path);
}

// A finished case: its record into the summary, its tip curve into case_NAME/tip_mm.csv, the
// result kept under its name.
void keep_result(const SuiteContext& ctx, GateResult r, std::map<std::string, GateResult>& results, SuiteSummary& summary) {
  summary.add_run(r.record);
  write_curve(r.x, r.y, ctx.out_dir / ("case_" + r.c.name) / "tip_mm.csv");
  const std::string name = r.c.name;
  results.emplace(name, std::move(r));
}

// The dry-bed dam break: the surge front against Martin & Moyce (1952) and Koshizuka & Oka (1996).
void run_dam_break(const SuiteContext& ctx, SuiteSummary& summary) {
  if (ctx.log) ctx.log("antoci: dry-bed dam break (free-surface sanity scene)");
  const Json refs = read_project_reference(ctx.project_dir, "dam_break_front.json");
  SceneRun run = run_scene(ctx, "dam_break.json", {});
  const double a = run.scene.parameters.at("a"), g = run.scene.parameters.at("g"), dp = run.scene.parameters.at("dp");
  const ObserverSeries& front = run.result.series.at(0);
  CsvTable table;
  table.columns = {"T", "Z"};
  std::vector<double> T, Z;
  for (std::size_t k = 0; k < front.time.size(); ++k) {
    T.push_back(front.time[k] * std::sqrt(2.0 * g / a));
    Z.push_back((front.values[k][0] + 0.5 * dp) / a);  // the front lies half a spacing beyond the last particle
    table.add_row({T.back(), Z.back()});
  }
  table.write(ctx.out_dir / "dam_break_front.csv");
  Json metrics = Json::object();
  for (const char* name : {"martin_moyce_a_2_25in", "koshizuka_oka"}) {
    const std::vector<double> rt = refs[name]["T"], rz = refs[name]["Z"];
    std::vector<double> t_in, z_in;
    for (std::size_t k = 0; k < rt.size(); ++k)
      if (rt[k] <= T.back()) { t_in.push_back(rt[k]); z_in.push_back(rz[k]); }
    if (const auto c = compare_curves(T, Z, t_in, z_in)) {
      metrics[std::string(name) + "_rms_error"] = c->rms_error;
      // Mean relative lead of the SPH front over the experiment.
      double lead = 0.0;
      for (std::size_t k = 0; k < t_in.size(); ++k) lead += interpolate(T, Z, t_in[k]) / z_in[k] - 1.0;
      metrics[std::string(name) + "_mean_relative_lead"] = lead / t_in.size();
    }
  }
  SuiteRun record;
  record.case_name = "dam break";
  record.config = {{"scene", "dam_break.json"}, {"resolution", run.scene.parameters.at("resolution")}};
  record.metrics = metrics;
  record.cost = cost_json(run);
  record.compressibility = compressibility_record(run);
  record.diverged = run.result.divergence.has_value();
  record.divergence = divergence_record(run);
  summary.add_run(std::move(record));
  if (record.diverged) {
    summary.check_missing("dam break runs (free surface stays well-behaved)", "diverged", "issue 5");
    return;
  }
  // An inviscid SPH front runs ahead of Martin & Moyce's: their gate took time to lift and the bed
  // had friction (the lead of 10-20 % is common in SPH papers). A sanity bound, not a validation.
  summary.check_range("dam-break front lead over Martin & Moyce (mean relative)",
                      metrics.value("martin_moyce_a_2_25in_mean_relative_lead", double(NAN)), -0.05, 0.25,
                      "Martin & Moyce (1952), reference-data/dam_break_front.json; sanity bound for an inviscid front");
}

// The convergence of the specified model (full mode): the gate on a grid of fluid spacings dp_F =
// 2.5 and 1.25 mm and solid spacings b/dp_S = 4, 8, 16 (ratios 1-8), each with both kinds of
// gradient weights, and case II's fluid (0.625 mm, b/8) with B0. Points equal to a case above (I,
// II, III, III-B0) are taken from it; the others run concurrently with --jobs. It shows where the
// discretisation converges to, and so what the experiment's criteria ask of the model itself.
void run_convergence_grid(const SuiteContext& ctx, const std::optional<Curve>& exp_x, const std::optional<Curve>& exp_y,
                          std::map<std::string, GateResult>& results, SuiteSummary& summary) {
  struct GridPoint {
    double dp_fluid_mm;
    int resolution;
    std::string weights;
    std::string name;  // the case's name
  };
  const auto weights_label = [](const std::string& w) { return w == "first_order" ? std::string("B0") : std::string("2nd"); };
  std::vector<GridPoint> grid;
  for (const double dp_fluid_mm : {2.5, 1.25})
    for (const int resolution : {4, 8, 16})
      for (const char* weights : {"second_order", "first_order"})
        grid.push_back({dp_fluid_mm, resolution, weights, ""});
  grid.push_back({0.625, 8, "second_order", ""});
  grid.push_back({0.625, 8, "first_order", ""});
  const double b_mm = 5.0;  // the gate's thickness (elastic_gate.json)
  std::vector<GateCase> to_run;
  for (GridPoint& g : grid) {
    const int ratio = static_cast<int>(std::lround(g.dp_fluid_mm * g.resolution / b_mm));
    for (const auto& [name, r] : results)
      if (r.c.ratio == ratio && r.c.resolution == g.resolution && r.c.gradient_correction == g.weights &&
          r.c.schedule == "multi_step_position_verlet" && !r.c.damping && r.c.kinematics.empty())
        g.name = name;
    if (!g.name.empty()) continue;
    g.name = fmt::format("grid-F{:g}-b{}-{}", g.dp_fluid_mm, g.resolution, weights_label(g.weights));
    GateCase c{g.name, ratio, g.resolution, "multi_step_position_verlet"};
    c.gradient_correction = g.weights;
    to_run.push_back(c);
  }
  // Longest first, so that concurrent runs finish together: the solid's cost grows as (b/dp_S)^3
  // (particles and sub-steps; the second-order weights take twice the sub-steps), the fluid's as
  // dp_F^-3; seconds on one thread, measured for cases I and III.
  const auto estimated_cost = [&](const GateCase& c) {
    const double dp_fluid_mm = b_mm * c.ratio / c.resolution;
    return 5.0 * std::pow(c.resolution / 4.0, 3) * (c.gradient_correction == "first_order" ? 0.5 : 1.0) +
           6.0 * std::pow(2.5 / dp_fluid_mm, 3);
  };
  std::stable_sort(to_run.begin(), to_run.end(),
                   [&](const GateCase& a, const GateCase& b) { return estimated_cost(a) > estimated_cost(b); });
  std::vector<GateResult> ran(to_run.size());
  run_cases(ctx, to_run.size(), [&](const SuiteContext& case_ctx, std::size_t k) {
    ran[k] = run_case(case_ctx, to_run[k], exp_x, exp_y, false);
  });
  for (GateResult& r : ran) keep_result(ctx, std::move(r), results, summary);

  Json table = Json::array();
  for (const GridPoint& g : grid) {
    const GateResult& r = results.at(g.name);
    Json row = {{"case", g.name}, {"dp_fluid_mm", g.dp_fluid_mm}, {"resolution", g.resolution}, {"ratio", r.c.ratio},
                {"weights", weights_label(g.weights)}, {"wall_s", r.wall_s}, {"diverged", r.diverged}};
    for (const char* key : {"peak_x_mm", "peak_time_s", "rms_error_x_mm", "rms_error_x_loading_mm", "max_error_x_mm"})
      row[key] = r.metrics.contains(key) ? r.metrics[key] : Json(nullptr);
    table.push_back(row);
  }
  summary.extra()["convergence"] = table;

  // Both kinds of weights are consistent, so they must converge to one answer: at each fluid spacing
  // the RMS distance between their tip curves (0-0.4 s) should shrink as the solid is refined. B0 is
  // first-order accurate (the gradient of a linear field exact), so four times finer should divide
  // its error by at least about four; the check asks for half of that.
  const auto name_of = [&](double dp_fluid_mm, int resolution, const std::string& weights) {
    for (const GridPoint& g : grid)
      if (g.dp_fluid_mm == dp_fluid_mm && g.resolution == resolution && g.weights == weights) return g.name;
    return std::string();
  };
  Json distance = Json::object();
  for (const double dp_fluid_mm : {2.5, 1.25}) {
    double gap[2] = {NAN, NAN};
    for (int k = 0; k < 2; ++k) {
      const GateResult& b0 = results.at(name_of(dp_fluid_mm, k == 0 ? 4 : 16, "first_order"));
      const GateResult& second = results.at(name_of(dp_fluid_mm, k == 0 ? 4 : 16, "second_order"));
      if (b0.diverged || second.diverged) continue;
      if (const auto d = compare_curves(b0.x.t, b0.x.value, second.x.t, second.x.value)) gap[k] = d->rms_error;
    }
    distance[fmt::format("{:g}", dp_fluid_mm)] = {{"b4_mm", gap[0]}, {"b16_mm", gap[1]}};
    summary.check_at_most(fmt::format("gate tip curves of B0 and the second-order weights converge together (dp_F = {:g} mm): "
                                      "RMS distance at b/16 over that at b/4", dp_fluid_mm),
                          gap[1] / gap[0], 0.5,
                          "consistency of both discretisations; first-order convergence would give 0.25 for a 4 times finer solid");
  }
  summary.extra()["convergence_weights_distance"] = distance;
}

struct Experiment {
  std::optional<Curve> x, y;  // mm, first sample subtracted
};

void write_reference_curves(const SuiteContext& ctx, const std::filesystem::path& dir, const Experiment& exp) {
  for (const char* name : {"Antoci_x.txt", "Antoci_y.txt", "YangEtAl10X.txt", "YangEtAl10Y.txt"})
    if (const auto c = read_reference_curve(dir / name)) {
      CsvTable t;
      t.columns = {"time", "mm"};
      for (std::size_t k = 0; k < c->t.size(); ++k) t.add_row({c->t[k], c->value[k]});
      t.write(ctx.out_dir / fmt::format("reference_{}.csv", std::filesystem::path(name).stem().string()));
    }
  if (exp.x) {
    CsvTable t;
    t.columns = {"time", "x_mm", "y_mm"};
    for (std::size_t k = 0; k < exp.x->t.size(); ++k)
      t.add_row({exp.x->t[k], exp.x->value[k], exp.y ? interpolate(exp.y->t, exp.y->value, exp.x->t[k]) : NAN});
    t.write(ctx.out_dir / "reference_experiment.csv");
  }
  // The paper's code run here (time in ms, position in mm).
  if (const auto peer = read_numeric_table(*ctx.reference_dir / "sphinxsys" / "runs-here" / "elastic_gate_Observer_Position.dat")) {
    CsvTable t;
    t.columns = {"time", "x_mm", "y_mm"};
    const double x0 = peer->columns[1].front(), y0 = peer->columns[2].front();
    for (std::size_t k = 0; k < peer->columns[0].size(); ++k)
      t.add_row({peer->columns[0][k] / 1000.0, x0 - peer->columns[1][k], peer->columns[2][k] - y0});
    t.write(ctx.out_dir / "reference_sphinxsys_here.csv");
  }
}

// The experiment's curves (Ex10X, Ex10Y), and every reference curve written beside the run's for the
// figure (other methods' curves, the paper's code run here); skips said in the summary.
Experiment read_experiment(const SuiteContext& ctx, SuiteSummary& summary) {
  Experiment exp;
  if (ctx.reference_dir) {
    const auto dir = *ctx.reference_dir / "antoci2007";
    exp.x = read_reference_curve(dir / "Ex10X.txt");
    exp.y = read_reference_curve(dir / "Ex10Y.txt");
    if (!exp.x) summary.note_skipped("experiment comparison (x)", (dir / "Ex10X.txt").string() + " is missing");
    if (!exp.y) summary.note_skipped("experiment comparison (y)", (dir / "Ex10Y.txt").string() + " is missing");
    write_reference_curves(ctx, dir, exp);
  } else {
    summary.note_skipped("comparison with the experiment and the peer curves",
                         "no --reference-dir given (pass ../shared/reference-data)");
  }
  return exp;
}

// The cases to run: the paper's I-IV (quick: III) and case III's variants.
std::vector<GateCase> gate_cases(const SuiteContext& ctx) {
  // III-B0: case III with the paper's kernel correction instead of the second-order weights: at four
  // particles through the gate's thickness B0 is softer in bending (oscillating-plate suite), which
  // shows how much of the agreement with the experiment the discretisation error carries.
  // The variants below are case III with one thing changed.
  const GateCase case_III{"III", 2, 4, "multi_step_position_verlet"};
  GateCase paper_weights = case_III;
  paper_weights.name = "III-B0";
  paper_weights.gradient_correction = "first_order";
  std::vector<GateCase> cases;
  if (ctx.quick) cases = {case_III, paper_weights};
  else cases = {{"I", 1, 4, "multi_step_position_verlet"}, {"II", 1, 8, "multi_step_position_verlet"},
                case_III, {"IV", 2, 4, "single_step_position_verlet"}, paper_weights};
  // The damping study (reports/antoci.md): case III without the Kelvin-Voigt damping, with the
  // averaged and the instantaneous solid kinematics, and with twice the damping.
  if (!ctx.quick) {
    GateCase undamped = case_III, undamped_instantaneous = case_III, damped_more = case_III;
    undamped.name = "III-undamped";
    undamped.damping = 0.0;
    undamped_instantaneous.name = "III-undamped-instantaneous";
    undamped_instantaneous.damping = 0.0;
    undamped_instantaneous.kinematics = "instantaneous";
    damped_more.name = "III-damping-0.2";
    damped_more.damping = 0.2;
    // Case I (the fluid as fine as the solid) with the fluid's kernel 2.0 dp_F wide instead of 1.3.
    GateCase wide_kernel{"I-h2", 1, 4, "multi_step_position_verlet"};
    wide_kernel.fluid_h_over_dp = 2.0;
    for (const GateCase& c : {undamped, undamped_instantaneous, damped_more, wide_kernel}) cases.push_back(c);
  }
  return cases;
}

// Case III against the experiment's peak and curve (a diverged case III is a failed check).
void check_against_experiment(const SuiteContext& ctx, const GateResult& III, const Experiment& exp, SuiteSummary& summary) {
  const Peak peak_x = peak_of(exp.x), peak_y = peak_of(exp.y);
  const std::string issue = "issue 5 acceptance; experiment Antoci et al. 2007 (first sample subtracted)";
  if (III.diverged) {
    summary.check_missing("case III runs to t = 0.4 s", "diverged", issue);
  } else if (exp.x) {
    summary.check_near("case III peak x [mm]", metric(III, "peak_x_mm"), peak_x.value, 0.1 * peak_x.value,
                       issue + fmt::format(": peak {:.1f} mm +/- 10 %", peak_x.value));
    if (exp.y)
      summary.check_near("case III peak y [mm]", metric(III, "peak_y_mm"), peak_y.value, 0.1 * peak_y.value,
                         fmt::format("experiment: vertical peak {:.1f} mm (first sample subtracted) +/- 10 %", peak_y.value));
    if (ctx.quick) {
      // Quick mode checks the loading phase, where a linear elastic gate should follow the
      // experiment; the closing phase depends on the rubber's behaviour beyond linear elasticity
      // (paper section 4.2) and is judged in full mode.
      summary.check_at_most("case III RMS error of x in the loading phase (t <= 0.125 s) [mm]",
                            metric(III, "rms_error_x_loading_mm"), 5.0,
                            "experiment frames at 0.04-0.12 s; tolerance as the issue's 5 mm over the whole window");
    } else {
      summary.check_at_most("case III RMS error of x against the experiment [mm]", metric(III, "rms_error_x_mm"), 5.0, issue);
      summary.check_near("case III peak time [s]", metric(III, "peak_time_s"), peak_x.time, 0.03,
                         issue + fmt::format(": {:.3f} s +/- 0.03 s", peak_x.time));
    }
  }
}

// The damping acts on noise only; multiple steps pay; case III's wall time.
void check_damping_and_cost(const SuiteContext& ctx, const std::map<std::string, GateResult>& results, SuiteSummary& summary) {
  const GateResult& III = results.at("III");
  if (!ctx.quick && !III.diverged) {
    // The damping is there to remove particle-scale noise (below), not to change the gate's
    // response: twice the coefficient must leave the peak where it is. 1 mm is 2 % of the peak,
    // a fifth of the issue's 5 mm RMS budget.
    const GateResult& more = results.at("III-damping-0.2");
    summary.check_at_most("case III peak x changes by less than 1 mm when the damping goes from 0.1 to 0.2 [mm]",
                          std::abs(metric(more, "peak_x_mm") - metric(III, "peak_x_mm")), 1.0,
                          "the damping must act on particle-scale noise only (reports/antoci.md, damping study)");
    // Nor may the fluid's kernel width, another numerical parameter, move the gate once the fluid is
    // fine (case I, dp_F = dp_S): the same 1 mm on the peak and on the RMS error against the experiment.
    // Measured: 0.01 and 0.15 mm; case III's coarser fluid moves by 2.2 and 0.7 mm (pressure.md section 33).
    const GateResult &I = results.at("I"), &wide = results.at("I-h2");
    const std::string source = "a numerical parameter must not move the answer; reports/pressure.md section 33";
    for (const char* m : {"peak_x_mm", "rms_error_x_mm"})
      summary.check_at_most(fmt::format("case I {} changes by less than 1 mm when h goes from 1.3 to 2.0 dp_F [mm]", m),
                            std::abs(metric(wide, m) - metric(I, m)), 1.0, source);
  }
  if (!ctx.quick) {
    const GateResult& IV = results.at("IV");
    summary.check_range("speed-up of multiple over single time steps (wall IV / wall III)", IV.wall_s / III.wall_s, 1.0, 1e9,
                        "issue 5: the paper measures 4.8");
    if (ctx.threads == 2)
      summary.check_at_most("case III wall time to t = 0.4 s on 2 threads [s]", III.wall_s, 6.0,
                            "issue 5 acceptance; the paper's code takes 10-15 s here (runs-here)");
    else
      summary.note_skipped("case III wall-time check", "needs --threads 2 (the acceptance is stated for 2 threads)");
  }
}

// The cases beside the paper's CPU times, the experiment's peak, the paper's code run here.
void add_tables(const SuiteContext& ctx, const std::map<std::string, GateResult>& results, const Experiment& exp,
                SuiteSummary& summary) {
  const GateResult& III = results.at("III");
  const Peak peak_x = peak_of(exp.x), peak_y = peak_of(exp.y);
  const Json refs = read_project_reference(ctx.project_dir, "antoci_gate.json");
  const Json& paper = refs["paper_cpu_s"];
  Json table = Json::array();
  for (const auto& [name, r] : results)
    table.push_back({{"case", name}, {"ratio", r.c.ratio}, {"resolution", r.c.resolution}, {"schedule", r.c.schedule},
                     {"wall_s", r.wall_s}, {"paper_cpu_s", paper.value(name, double(NAN))}, {"metrics", r.metrics}});
  summary.extra()["table"] = table;
  if (results.count("IV")) summary.extra()["speedup_III_vs_IV"] = {{"ours", results.at("IV").wall_s / III.wall_s}, {"paper", paper["IV"].get<double>() / paper["III"].get<double>()}};
  if (exp.x) summary.extra()["experiment_peak"] = {{"x_mm", peak_x.value}, {"time_s", peak_x.time}, {"y_mm", peak_y.value}};
  summary.extra()["paper_code_here"] = refs["paper_code_here"];
}

}  // namespace

SuiteSummary run_antoci_suite(const SuiteContext& ctx) {
  SuiteSummary summary("antoci", ctx.quick, ctx.threads);
  const Experiment exp = read_experiment(ctx, summary);
  std::map<std::string, GateResult> results;
  for (const GateCase& c : gate_cases(ctx)) keep_result(ctx, run_case(ctx, c, exp.x, exp.y, c.name == "III"), results, summary);
  check_against_experiment(ctx, results.at("III"), exp, summary);
  check_damping_and_cost(ctx, results, summary);
  if (!ctx.quick) run_convergence_grid(ctx, exp.x, exp.y, results, summary);
  run_dam_break(ctx, summary);
  add_tables(ctx, results, exp, summary);
  summary.write(ctx.out_dir);
  render_figures(ctx, "plot_antoci.py", summary);
  summary.write(ctx.out_dir);
  return summary;
}

}  // namespace mrsph::verification
