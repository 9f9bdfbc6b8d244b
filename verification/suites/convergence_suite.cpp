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
#include "suites/scene_run.hpp"
#include "suites/turek_hron_suite.hpp"
#include "sweep/sweep.hpp"

#include <fmt/format.h>

#include <cmath>

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
    if (const auto c = three_grid_convergence(values[n - 3], values[n - 2], values[n - 1], 2.0)) {
      j["observed_order"] = c->observed_order;
      j["extrapolated"] = c->extrapolated;
      j["gci"] = c->gci;
      j["monotone"] = c->monotone;
    }
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

}  // namespace

SuiteSummary run_convergence_suite(const SuiteContext& ctx) {
  SuiteSummary summary("convergence", ctx.quick, ctx.threads);
  std::vector<SweepRun> runs;
  std::vector<Ladder> ladders;

  Ladder plate{"plate", ctx.quick ? std::vector<int>{4, 8, 16} : std::vector<int>{4, 8, 16, 32}, {}};
  for (int res : plate.rungs) {
    SweepRun r;
    r.label = fmt::format("plate H/dp={}", res);
    r.scene = "oscillating_plate.json";
    r.overrides = {fmt::format("parameters.resolution={}", res), "parameters.periods=3.5"};
    r.config = {{"ladder", "plate"}, {"resolution", res}};
    plate.run_index.push_back(runs.size());
    runs.push_back(r);
  }
  ladders.push_back(plate);
  if (!ctx.quick) {
    Ladder gate{"gate", {4, 8, 16}, {}};
    for (int res : gate.rungs) {
      SweepRun r;
      r.label = fmt::format("gate b/dp_S={}", res);
      r.scene = "elastic_gate.json";
      r.overrides = {fmt::format("parameters.resolution={}", res)};
      r.config = {{"ladder", "gate"}, {"resolution", res}};
      gate.run_index.push_back(runs.size());
      runs.push_back(r);
    }
    ladders.push_back(gate);
    Ladder fsi2{"FSI2", {4, 8, 16}, {}};
    for (int res : fsi2.rungs) {
      SweepRun r = fsi2_sweep_run(FsiCase{res == 4 ? "III" : fmt::format("III-{}", res), 2, res, "multi_step_position_verlet"}, 200.0);
      r.config["ladder"] = "FSI2";
      fsi2.run_index.push_back(runs.size());
      runs.push_back(r);
    }
    ladders.push_back(fsi2);
  }

  const std::vector<SweepOutcome> outcomes = sweep(ctx, runs, summary);
  if (outcomes.empty()) {
    summary.write(ctx.out_dir);
    return summary;
  }

  std::optional<std::vector<double>> exp_t, exp_x;
  if (ctx.reference_dir)
    if (const auto t = read_numeric_table(*ctx.reference_dir / "antoci2007" / "Ex10X.txt")) {
      exp_t = t->columns[0];
      exp_x = std::vector<double>();
      for (double v : t->columns[1]) exp_x->push_back(1000.0 * (v - t->columns[1].front()));
    }

  Json results = Json::object();
  for (const Ladder& ladder : ladders) {
    std::map<std::string, std::vector<double>> metric_values;
    for (std::size_t k = 0; k < ladder.rungs.size(); ++k) {
      const SweepOutcome& o = outcomes[ladder.run_index[k]];
      SuiteRun record;
      record.case_name = ladder.name == "FSI2" ? fmt::format("FSI2 bh/dp_S={}", ladder.rungs[k]) : o.run.label;
      record.config = o.run.config;
      record.cost = o.cost;
      record.diverged = o.diverged;
      record.divergence = o.divergence;
      if (o.completed) {
        if (ladder.name == "plate") {
          record.metrics["period"] = plate_period(o);
          record.metrics["period_error"] = record.metrics["period"].get<double>() / (2.0 * M_PI / o.parameters.value("omega", NAN)) - 1.0;
        } else if (ladder.name == "gate") {
          record.metrics["peak_x_mm"] = gate_peak_mm(o);
          if (exp_t) {
            const ObserverSeries& tip = outcome_series(o, "gate_tip");
            std::vector<double> x;
            for (double dx : series_column(tip, 0)) x.push_back(-1000.0 * dx);
            if (const auto c = compare_curves(tip.time, x, *exp_t, *exp_x)) record.metrics["rms_error_x_mm"] = c->rms_error;
          }
        } else {
          record.metrics = fsi2_metrics(outcome_series(o, "tip"), outcome_series(o, "forces"), 200.0, 100.0);
        }
      } else {
        summary.check_missing(record.case_name + " completes", outcome_record(o).dump(), "convergence ladder");
      }
      for (auto it = record.metrics.begin(); it != record.metrics.end(); ++it)
        if (it.value().is_number()) metric_values[it.key()].push_back(it.value().get<double>());
      summary.add_run(std::move(record));
    }
    Json ladder_json = Json::object();
    for (const auto& [metric, values] : metric_values)
      if (values.size() == ladder.rungs.size()) ladder_json[metric] = ladder_convergence(values, ladder.rungs);
    results[ladder.name] = ladder_json;
  }
  summary.extra()["convergence"] = results;

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
  summary.write(ctx.out_dir);
  render_figures(ctx, "plot_convergence.py", summary);
  summary.write(ctx.out_dir);
  return summary;
}

}  // namespace mrsph::verification
