// verify --suite pressure: Schaefer & Turek's (1996) cylinder benchmarks 2D-1 (Re = 20, steady) and
// 2D-2 (Re = 100, periodic), the cylinder of Turek & Hron's CFD tests without the beam, in the
// benchmark's 22 D channel (scene schaefer_turek_cylinder.json). Besides the forces the benchmark
// gives the pressure difference between the cylinder's front and rear points, a check of the
// pressure field itself, and without the beam the wake sheds from the cylinder alone
// (reports/pressure.md section 28).
// Coefficients: the benchmark's c = 2 F / (rho U^2 D); the scene's force observer writes F / (rho U^2 D),
// so the references are halved here. Pressures in rho U^2, as the benchmark's delta p at U = 1 m/s
// (2D-2) and delta p / (rho U^2) = delta p / 0.04 Pa (2D-1).
// Plan: quick, 2D-1 at D/dp = 10, c = 10 U0; full, both at D/dp = 10, 20, 40 (c = 10 U0) and at
// D/dp = 20 also c = 40 U0. Both modes: 2D-1 at D/dp = 10, c = 20 U0 with the linear pressure
// reference, the outlet at 0 and at 5 rho U0^2 (the datum's check).
#include "suites/pressure_suite.hpp"

#include "report/reference_table.hpp"
#include "suites/scene_run.hpp"

namespace mrsph::verification {

void run_schaefer_turek(const SuiteContext& ctx, SuiteSummary& summary) {
  const Json refs = read_project_reference(ctx.project_dir, "schaefer_turek_cylinder.json");
  const std::string source = "Schaefer & Turek (1996) 2D-1 and 2D-2, reference-data/schaefer_turek_cylinder.json; tolerances of issue 17";
  // The inflow ramps over t = 10 and starts the channel's quarter-wave acoustic mode (a velocity
  // inlet and a pressure outlet 22.4 D apart: period 4 L / c = 9 at c = 10 U0), which moves 2D-1's
  // drag by +-5 % over t = 15-25 and +-3 % over t = 30-40 and decays slowly: 2D-1's window holds two
  // of its periods at c = 10 U0 (eight at 40 U0). 2D-2 sheds from t = 25 at D/dp = 20 (St 0.3:
  // 12 periods over t = 40-80, the acoustic mode's 4.4). Its band (St 0.15-0.5) holds the shedding
  // line and leaves out the drag's at 0.6.
  const BenchmarkCase steady{"2D-1", 20.0, 50.0, 32.0, false};
  const BenchmarkCase periodic{"2D-2", 100.0, 80.0, 40.0, true, 0.15, 0.5};
  const std::string scene = "schaefer_turek_cylinder.json";
  std::vector<CylinderRun> runs;
  // The outlet's pressure is a datum: with the linear pressure reference (an option) 2D-1's drag may
  // move with it only as the fluid's compression p0 / (rho0 c^2) moves the density (pressure.md
  // section 30). D/dp = 10 and c = 20 U0: 1.25 % at p0 = 5 rho U0^2, where the plain force moves 10 %.
  const std::string linear = R"(fluid.pressure_reference="linear")";
  const double datum = 5.0;
  const int datum_factor = 20;
  const std::string at_zero = "linear reference", at_datum = fmt::format("linear reference, outlet at {:g}", datum);
  if (ctx.quick) {
    runs.push_back({&steady, 10, 10, {}, scene});
  } else {
    for (int res : {40, 20, 10})  // longest first, so that concurrent runs end together
      for (const BenchmarkCase* b : {&periodic, &steady}) {
        if (res == 20) runs.push_back({b, 20, 40, {}, scene});
        runs.push_back({b, res, 10, {}, scene});
      }
  }
  runs.push_back({&steady, 10, datum_factor, {}, scene, at_zero, {linear}});  // short: after the ladder
  runs.push_back({&steady, 10, datum_factor, {}, scene, at_datum, {linear, fmt::format("parameters.outlet_pressure={:g}", datum)}});
  run_cases(ctx, runs.size(), [&](const SuiteContext& case_ctx, std::size_t k) { run_cylinder(case_ctx, runs[k]); });
  for (const CylinderRun& r : runs) summary.add_run(r.record);

  const CylinderResults results(runs);
  const Json& one = refs["2D-1"];
  const double drag = 0.5 * one["drag_coefficient"].get<double>();
  const double pressure_difference = one["pressure_difference_Pa"].get<double>() / one["rho_U2_Pa"].get<double>();
  if (ctx.quick) {
    // 10 particles across the cylinder, as CFD2's coarse check (pressure_suite.cpp): 10 %.
    check_relative_or_missing(summary, "2D-1 drag at D/dp=10", results.value("2D-1", 10, 10, "drag_mean"), drag, 0.10,
                              source + " (coarse resolution: 10 %)");
    check_relative_or_missing(summary, "2D-1 pressure difference at D/dp=10", results.value("2D-1", 10, 10, "pressure_difference_mean"),
                              pressure_difference, 0.10, source + " (coarse resolution: 10 %)");
  } else {
    // The drag and the shedding depend on the outlet's pressure, physically a datum, through the
    // pressure force's zero-order error (reports/pressure.md section 28): these checks read the
    // scene's p = 0 outlet.
    // Issue 17's tolerances for the drag, lift, St and lift amplitude of the CFD tests at D/dp = 20;
    // the pressure difference as the drag (3 %). 2D-1's lift (c_L 0.011, 0.5 % of the drag) is below
    // the particles' noise and is recorded, not checked.
    check_relative_or_missing(summary, "2D-1 drag at D/dp=20", results.value("2D-1", 20, 10, "drag_mean"), drag, 0.03, source);
    check_relative_or_missing(summary, "2D-1 pressure difference at D/dp=20", results.value("2D-1", 20, 10, "pressure_difference_mean"),
                              pressure_difference, 0.03, source);
    const Json& two = refs["2D-2"];
    const auto middle = [&](const char* key) { return 0.5 * (two[key][0].get<double>() + two[key][1].get<double>()); };
    check_relative_or_missing(summary, "2D-2 Strouhal number at D/dp=20", results.value("2D-2", 20, 10, "strouhal_shedding"),
                              middle("strouhal_bounds"), 0.02, source + " (the middle of the published bounds)");
    // c_L,max / 2: the lift's mean plus its shedding component's amplitude.
    const double lift_max = results.value("2D-2", 20, 10, "lift_mean") + results.value("2D-2", 20, 10, "lift_shedding_amplitude");
    check_relative_or_missing(summary, "2D-2 largest lift at D/dp=20", lift_max, 0.5 * middle("lift_coefficient_max_bounds"), 0.10,
                              source + " (the middle of the published bounds)");
    check_sound_speed_independence(summary, results, "2D-1", 20, 10, 40, 0.02, source + " (O(Mach^2) = 1 % at c = 10 U0)");
  }
  // Linear EOS: the density at p0 is rho0 (1 + p0 / (rho0 c^2)); only the pressure part of the drag
  // follows it (about two thirds of 2D-1's), so the whole drag's share is an upper bound.
  check_relative_or_missing(summary, "2D-1 drag with the linear reference: outlet at 5 against 0 (D/dp=10, c=20U0)",
                            results.value("2D-1", 10, datum_factor, "drag_mean", at_datum),
                            results.value("2D-1", 10, datum_factor, "drag_mean", at_zero), datum / (datum_factor * datum_factor),
                            "incompressible flow does not see a datum; the fluid's compression p0 / (rho0 c^2) = 1.25 % bounds the "
                            "weakly compressible drag's change (reports/pressure.md section 30)");
  const std::vector<BenchmarkCase> cases{steady, periodic};
  summary.extra()["schaefer_turek_convergence"] =
      convergence_table(results, cases, ctx.quick ? std::vector<int>{10} : std::vector<int>{10, 20, 40}, 10);
  summary.extra()["schaefer_turek_reference"] = refs;
}

}  // namespace mrsph::verification
