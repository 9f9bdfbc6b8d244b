// verify --suite convergence: resolution ladders (refinement ratio 2) with, per metric, the observed
// order, the Richardson-extrapolated value and Roache's grid convergence index (metrics/convergence.hpp):
//   plate   H/dp = 4, 8, 16 (full: 32), SVK, second-order weights: period (and its error against
//           Euler-Bernoulli)
//   gate    b/dp_S = 4, 8, 16 at dp_F/dp_S = 2 (full only): peak and RMS error of the free end
//   FSI2    bh/dp_S = 4, 8, 16 at dp_F/dp_S = 2, to t = 200 (full only): A_y/D and St, beside the
//           paper's Table 3. bh/dp_S = 4 is case III and is shared with the turek-hron suite.
#include "suites/convergence_suite.hpp"

#include "metrics/convergence.hpp"
#include "metrics/signal_metrics.hpp"
#include "report/reference_table.hpp"
#include "suites/gate_experiment.hpp"
#include "suites/scene_run.hpp"
#include "suites/turek_hron_suite.hpp"
#include "sweep/sweep.hpp"

#include <fmt/format.h>

#include <cmath>
#include <functional>

namespace mrsph::verification {

namespace {

struct Ladder {
  std::string name;
  std::vector<int> rungs;
  std::vector<std::size_t> run_index;  // into the sweep
};

Json ladder_convergence(const std::vector<double>& values, const std::vector<int>& rungs) {
  Json j = {{"resolutions", rungs}, {"values", values}};
  if (values.size() >= 3) {
    const std::size_t n = values.size();
    if (const auto c = three_grid_convergence(values[n - 3], values[n - 2], values[n - 1], 2.0))
      write_estimate(*c, j);
  }
  return j;
}

double plate_period(const SweepOutcome& o) {
  const ObserverSeries& tip = outcome_series(o, "tip");
  const auto s = oscillation_stats(tip.time, series_column(tip, 1), 0.0);
  return s ? 1.0 / s->frequency : NAN;
}

double gate_peak_mm(const SweepOutcome& o) {
  const ObserverSeries& tip = outcome_series(o, "gate_tip");
  double peak = -INFINITY;
  for (const double dx : series_column(tip, 0)) peak = std::max(peak, -1000.0 * dx);
  return peak;
}

// The ladders (plate; full mode: gate and FSI2) and their runs, in one sweep.
struct Plan {
  std::vector<SweepRun> runs;
  std::vector<Ladder> ladders;
  void add(Ladder ladder, const std::function<SweepRun(int)>& run_of) {
    for (int res : ladder.rungs) {
      ladder.run_index.push_back(runs.size());
      runs.push_back(run_of(res));
    }
    ladders.push_back(std::move(ladder));
  }
};

Plan plan_ladders(const SuiteContext& ctx) {
  Plan plan;
  plan.add({"plate", ctx.quick ? std::vector<int>{4, 8, 16} : std::vector<int>{4, 8, 16, 32}, {}}, [](int res) {
    SweepRun r;
    r.label = fmt::format("plate H/dp={}", res);
    r.scene = "oscillating_plate.json";
    r.overrides = {fmt::format("parameters.resolution={}", res), "parameters.periods=3.5"};
    r.config = {{"ladder", "plate"}, {"resolution", res}};
    return r;
  });
  if (ctx.quick) return plan;
  plan.add({"gate", {4, 8, 16}, {}}, [](int res) {
    SweepRun r;
    r.label = fmt::format("gate b/dp_S={}", res);
    r.scene = "elastic_gate.json";
    r.overrides = {fmt::format("parameters.resolution={}", res)};
    r.config = {{"ladder", "gate"}, {"resolution", res}};
    return r;
  });
  plan.add({"FSI2", {4, 8, 16}, {}}, [](int res) {
    SweepRun r = fsi2_sweep_run(FsiCase{res == 4 ? "III" : fmt::format("III-{}", res), 2, res, "multi_step_position_verlet"}, 200.0);
    r.config["ladder"] = "FSI2";
    return r;
  });
  return plan;
}

// The metrics of one completed rung.
Json rung_metrics(const std::string& ladder, const SweepOutcome& o, const std::optional<Curve>& gate_x) {
  Json m = Json::object();
  if (ladder == "plate") {
    m["period"] = plate_period(o);
    m["period_error"] = m["period"].get<double>() / (2.0 * M_PI / o.parameters.value("omega", double(NAN))) - 1.0;
  } else if (ladder == "gate") {
    m["peak_x_mm"] = gate_peak_mm(o);
    if (gate_x)
      if (const auto rms = gate_rms_error_mm(outcome_series(o, "gate_tip"), *gate_x)) m["rms_error_x_mm"] = *rms;
  } else {
    m = fsi2_metrics(outcome_series(o, "tip"), outcome_series(o, "forces"), 200.0, 100.0);
  }
  return m;
}

// Each rung recorded in the summary; the ladder's observed order and Richardson value per metric.
Json measure_ladder(const Ladder& ladder, const std::vector<SweepOutcome>& outcomes, const std::optional<Curve>& gate_x,
                    SuiteSummary& summary) {
  std::map<std::string, std::vector<double>> metric_values;
  for (std::size_t k = 0; k < ladder.rungs.size(); ++k) {
    const SweepOutcome& o = outcomes[ladder.run_index[k]];
    SuiteRun record;
    record.case_name = ladder.name == "FSI2" ? fmt::format("FSI2 bh/dp_S={}", ladder.rungs[k]) : o.run.label;
    record.config = o.run.config;
    record.cost = o.cost;
    record.diverged = o.diverged;
    record.divergence = o.divergence;
    if (o.completed) record.metrics = rung_metrics(ladder.name, o, gate_x);
    else summary.check_missing(record.case_name + " completes", outcome_record(o).dump(), "convergence ladder");
    for (auto it = record.metrics.begin(); it != record.metrics.end(); ++it)
      if (it.value().is_number()) metric_values[it.key()].push_back(it.value().get<double>());
    summary.add_run(std::move(record));
  }
  Json ladder_json = Json::object();
  for (const auto& [metric, values] : metric_values)
    if (values.size() == ladder.rungs.size()) ladder_json[metric] = ladder_convergence(values, ladder.rungs);
  return ladder_json;
}

void check_convergence(const SuiteContext& ctx, const Json& results, SuiteSummary& summary) {
  // The plate's period must converge at a consistent order: between 1 and 3 for this scheme
  // (first-order consistent gradients at the surface, second-order inside).
  if (results["plate"].contains("period") && results["plate"]["period"].contains("observed_order"))
    summary.check_range("plate period: observed order", results["plate"]["period"]["observed_order"].get<double>(), 1.0, 3.0,
                        "a consistent discretisation converges; order between the surface's and the interior's");
  if (!ctx.quick && results.contains("FSI2") && results["FSI2"].contains("strouhal")) {
    const Json refs = read_project_reference(ctx.project_dir, "turek_hron_fsi2.json");
    summary.extra()["paper_table_3"] = refs["paper_table_3"];
    const double finest = results["FSI2"]["strouhal"]["values"].back();
    summary.check_range("FSI2 finest rung (bh/dp_S = 16) strouhal in the published range", finest,
                        refs["published_range"]["strouhal"][0], refs["published_range"]["strouhal"][1],
                        refs["published_range"]["source"]);
  }
}

}  // namespace

SuiteSummary run_convergence_suite(const SuiteContext& ctx) {
  SuiteSummary summary("convergence", ctx.quick, ctx.threads);
  const Plan plan = plan_ladders(ctx);
  const std::vector<SweepOutcome> outcomes = sweep(ctx, plan.runs, summary);
  if (outcomes.empty()) {
    summary.write(ctx.out_dir);
    return summary;
  }
  const std::optional<Curve> gate_x = gate_experiment_x(ctx);
  Json results = Json::object();
  for (const Ladder& ladder : plan.ladders) results[ladder.name] = measure_ladder(ladder, outcomes, gate_x, summary);
  summary.extra()["convergence"] = results;
  check_convergence(ctx, results, summary);
  summary.write(ctx.out_dir);
  render_figures(ctx, "plot_convergence.py", summary);
  summary.write(ctx.out_dir);
  return summary;
}

}  // namespace mrsph::verification
