// verify --suite speed-accuracy: for each benchmark, configurations (resolution, resolution ratio,
// schedule, gradient weights) as points of wall time against error, the Pareto front (no other point
// is both faster and more accurate), and the recommendation: the cheapest configuration that meets
// each error target ("model no more than a scene needs").
//   plate   error = |period / Euler-Bernoulli - 1| (a ~1 % model floor: Timoshenko effects)
//   gate    error = RMS of the free end's x against the experiment [mm] (needs --reference-dir)
//   FSI2    error = max(|A_y/D / 0.806 - 1|, |St / 0.20 - 1|) against Turek & Hron (full mode only;
//           the turek-hron suite's cases are reused from the run cache)
// Runs are single-threaded (several at a time): wall times compare configurations, not thread counts.
#include "suites/speed_accuracy_suite.hpp"

#include "io/csv_table.hpp"
#include "metrics/signal_metrics.hpp"
#include "report/reference_table.hpp"
#include "suites/gate_experiment.hpp"
#include "suites/scene_run.hpp"
#include "suites/turek_hron_suite.hpp"
#include "sweep/sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace mrsph::verification {

namespace {

struct Point {
  std::string benchmark, label;
  double wall_s = NAN, error = NAN;
  bool pareto = false;
  Json config;
};

// The sweep's runs and, beside each, the benchmark it belongs to.
struct Plan {
  std::vector<SweepRun> runs;
  std::vector<std::string> benchmark;
  void add(SweepRun run, const std::string& name) {
    benchmark.push_back(name);
    runs.push_back(std::move(run));
  }
};

void plan_plate(const SuiteContext& ctx, Plan& plan) {
  for (const std::string correction : {"first_order", "second_order"})
    for (int res : ctx.quick ? std::vector<int>{4, 8} : std::vector<int>{4, 8, 16, 32}) {
      SweepRun r;
      r.label = fmt::format("plate H/dp={} {}", res, correction == "first_order" ? "B0" : "2nd order");
      r.scene = "oscillating_plate.json";
      r.overrides = {fmt::format("parameters.resolution={}", res), "parameters.periods=3.5",
                     fmt::format("solids[0].gradient_correction=\"{}\"", correction)};
      r.config = {{"resolution", res}, {"gradient_correction", correction}};
      plan.add(r, "plate");
    }
}

void plan_gate(const SuiteContext& ctx, Plan& plan, SuiteSummary& summary) {
  if (!ctx.reference_dir) {
    summary.note_skipped("gate points", "no --reference-dir: the error against the experiment cannot be measured");
    return;
  }
  struct GatePoint { int res, ratio; std::string schedule; };
  const std::vector<GatePoint> gate_points =
      ctx.quick ? std::vector<GatePoint>{{4, 2, "multi_step_position_verlet"}, {4, 4, "multi_step_position_verlet"}}
                : std::vector<GatePoint>{{4, 1, "multi_step_position_verlet"}, {4, 2, "multi_step_position_verlet"},
                                         {4, 4, "multi_step_position_verlet"}, {4, 2, "single_step_position_verlet"},
                                         {8, 1, "multi_step_position_verlet"}, {8, 2, "multi_step_position_verlet"},
                                         {8, 4, "multi_step_position_verlet"}};
  for (const GatePoint& g : gate_points) {
    SweepRun r;
    r.label = fmt::format("gate b/dp_S={} ratio {} {}", g.res, g.ratio, g.schedule == "single_step_position_verlet" ? "single" : "multi");
    r.scene = "elastic_gate.json";
    r.overrides = {fmt::format("parameters.resolution={}", g.res), fmt::format("parameters.ratio={}", g.ratio),
                   fmt::format("schedule.type=\"{}\"", g.schedule)};
    r.config = {{"resolution", g.res}, {"ratio", g.ratio}, {"schedule", g.schedule}};
    plan.add(r, "gate");
  }
}

void plan_fsi2(const SuiteContext& ctx, Plan& plan) {
  if (ctx.quick) return;
  for (const FsiCase& c : {FsiCase{"I", 1, 4, "multi_step_position_verlet"}, FsiCase{"II", 1, 8, "multi_step_position_verlet"},
                           FsiCase{"III", 2, 4, "multi_step_position_verlet"}, FsiCase{"IV", 2, 4, "single_step_position_verlet"},
                           FsiCase{"V", 4, 8, "multi_step_position_verlet"}, FsiCase{"III-8", 2, 8, "multi_step_position_verlet"}})
    plan.add(fsi2_sweep_run(c, 200.0), "FSI2");
}

// What each benchmark's error is measured against.
struct References {
  std::optional<Curve> gate_x;  // the gate experiment's x [mm] (gate_experiment.hpp)
  Json turek_hron;              // FSI2: A_y/D and St of Turek & Hron (2006)
};

References read_references(const SuiteContext& ctx) {
  References refs;
  refs.gate_x = gate_experiment_x(ctx);
  refs.turek_hron = read_project_reference(ctx.project_dir, "turek_hron_fsi2.json")["turek_hron_2006"];
  return refs;
}

// The error of one completed run (the file's header); NaN where it cannot be measured.
double error_of(const SweepOutcome& o, const std::string& benchmark, const References& refs) {
  if (benchmark == "plate") {
    const ObserverSeries& tip = outcome_series(o, "tip");
    if (const auto s = oscillation_stats(tip.time, series_column(tip, 1), 0.0))
      return std::abs(1.0 / s->frequency / (2.0 * M_PI / o.parameters.value("omega", double(NAN))) - 1.0);
  } else if (benchmark == "gate" && refs.gate_x) {
    return gate_rms_error_mm(outcome_series(o, "gate_tip"), *refs.gate_x).value_or(NAN);
  } else if (benchmark == "FSI2") {
    const Json m = fsi2_metrics(outcome_series(o, "tip"), outcome_series(o, "forces"), 200.0, 100.0);
    const Json& th = refs.turek_hron;
    if (m.contains("amplitude_y") && m.contains("strouhal"))
      return std::max(std::abs(m["amplitude_y"].get<double>() / th["amplitude_y"].get<double>() - 1.0),
                      std::abs(m["strouhal"].get<double>() / th["strouhal"].get<double>() - 1.0));
  }
  return NAN;
}

// One point per run, each recorded in the summary.
std::vector<Point> measure_points(const std::vector<SweepOutcome>& outcomes, const Plan& plan, const References& refs,
                                  SuiteSummary& summary) {
  std::vector<Point> points;
  for (std::size_t k = 0; k < outcomes.size(); ++k) {
    const SweepOutcome& o = outcomes[k];
    Point p{plan.benchmark[k], o.run.label, o.cost.value("wall_s", double(NAN)), NAN, false, o.run.config};
    if (o.completed) p.error = error_of(o, p.benchmark, refs);
    SuiteRun record;
    record.case_name = o.run.label;
    record.config = o.run.config;
    record.config["benchmark"] = p.benchmark;
    record.metrics = {{"error", p.error}};
    record.cost = o.cost;
    record.diverged = o.diverged;
    record.divergence = o.divergence;
    summary.add_run(std::move(record));
    points.push_back(p);
  }
  return points;
}

// Marks the Pareto front of one benchmark's points (sorted by time, a point is on the front if it is
// more accurate than every faster point) and returns them sorted by time.
std::vector<Point*> pareto_front(std::vector<Point>& points, const std::string& name) {
  std::vector<Point*> mine;
  for (Point& p : points)
    if (p.benchmark == name && std::isfinite(p.error) && std::isfinite(p.wall_s)) mine.push_back(&p);
  std::sort(mine.begin(), mine.end(), [](const Point* a, const Point* b) { return a->wall_s < b->wall_s; });
  double best = INFINITY;
  for (Point* p : mine)
    if (p->error < best) {
      p->pareto = true;
      best = p->error;
    }
  return mine;
}

// The cheapest configuration meeting each error target.
Json recommend(std::vector<Point>& points, const SuiteContext& ctx) {
  const std::map<std::string, std::vector<double>> targets = {
      {"plate", {0.1, 0.05, 0.02}}, {"gate", {8.0, 6.0, 5.0, 4.0}}, {"FSI2", {0.15, 0.10, 0.05}}};
  Json recommendations = Json::array();
  for (const auto& [name, levels] : targets) {
    const std::vector<Point*> mine = pareto_front(points, name);
    if (mine.empty()) continue;
    for (const double target : levels) {
      const auto it = std::find_if(mine.begin(), mine.end(), [&](const Point* p) { return p->error <= target; });
      Json rec = {{"benchmark", name}, {"target_error", target}};
      if (it == mine.end()) {
        rec["configuration"] = nullptr;
        rec["note"] = "no configuration of the sweep meets it";
      } else {
        rec["configuration"] = (*it)->label;
        rec["wall_s"] = (*it)->wall_s;
        rec["error"] = (*it)->error;
      }
      if (ctx.log)
        ctx.log(fmt::format("recommendation: {} error <= {:g}: {}", name, target,
                            it == mine.end() ? std::string("none in the sweep") : fmt::format("{} ({:.3g} s, error {:.3g})",
                                                                                             (*it)->label, (*it)->wall_s, (*it)->error)));
      recommendations.push_back(rec);
    }
  }
  return recommendations;
}

void write_points(const std::vector<Point>& points, const SuiteContext& ctx, SuiteSummary& summary) {
  CsvTable csv;
  csv.columns = {"benchmark", "index", "wall_s", "error", "pareto"};
  Json table = Json::array();
  const std::vector<std::string> names{"plate", "gate", "FSI2"};
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Point& p = points[k];
    csv.add_row({double(std::find(names.begin(), names.end(), p.benchmark) - names.begin()), double(k), p.wall_s, p.error, double(p.pareto)});
    table.push_back({{"benchmark", p.benchmark}, {"label", p.label}, {"wall_s", p.wall_s}, {"error", p.error},
                     {"pareto", p.pareto}, {"config", p.config}});
  }
  csv.write(ctx.out_dir / "speed_accuracy.csv");
  summary.extra()["points"] = table;
}

}  // namespace

SuiteSummary run_speed_accuracy_suite(const SuiteContext& ctx) {
  SuiteSummary summary("speed-accuracy", ctx.quick, ctx.threads);
  Plan plan;
  plan_plate(ctx, plan);
  plan_gate(ctx, plan, summary);
  plan_fsi2(ctx, plan);
  const std::vector<SweepOutcome> outcomes = sweep(ctx, plan.runs, summary);
  if (outcomes.empty()) {
    summary.write(ctx.out_dir);
    return summary;
  }
  std::vector<Point> points = measure_points(outcomes, plan, read_references(ctx), summary);
  const Json recommendations = recommend(points, ctx);  // marks the Pareto fronts first
  write_points(points, ctx, summary);
  summary.extra()["recommendations"] = recommendations;
  // No pass/fail here: against the gate experiment, coarse configurations can look better by error
  // cancellation (see reports/antoci.md); the chart and the recommendations are the result.
  summary.write(ctx.out_dir);
  render_figures(ctx, "plot_speed_accuracy.py", summary);
  summary.write(ctx.out_dir);
  return summary;
}

}  // namespace mrsph::verification
