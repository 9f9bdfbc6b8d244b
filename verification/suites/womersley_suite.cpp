// verify --suite womersley: the periodic plane channel driven by A cos(omega t) / rho, against the
// analytic Womersley profile (CASES.md; GSL complex functions, boundary/womersley_profile.hpp).
// Started from the analytic profile at t = 0 (the start-up transient from rest decays over many
// periods); the error is measured over the second period at 16 phases, on every fluid particle:
//   l2_error = sqrt( sum_{i,phase} (u_i - u_a(y_i, t))^2 / sum_{i,phase} u_a(y_i, t)^2 ).
#include "boundary/womersley_profile.hpp"
#include "io/csv_table.hpp"
#include "metrics/convergence.hpp"
#include "suites/scene_run.hpp"
#include "suites/womersley_suite.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace mrsph::verification {

namespace {

constexpr int kPhases = 16;

struct ProfileError {
  double err2 = 0.0, ref2 = 0.0, vertical2 = 0.0;
  long samples = 0;
  double l2() const { return ref2 > 0.0 ? std::sqrt(err2 / ref2) : NAN; }
  double vertical_ratio() const { return ref2 > 0.0 ? std::sqrt(vertical2 / ref2) : NAN; }
};

struct WomersleyRun {
  double wo;
  int resolution;
  ProfileError error;
  bool diverged;
};

WomersleyProfile profile_from(const LoadedScene& scene) {
  const ParameterTable& p = scene.parameters;
  WomersleyProfile w;
  w.channel_bottom = 0.0;
  w.channel_height = p.at("H");
  w.pressure_gradient_amplitude = p.at("A");
  w.angular_frequency = p.at("omega");
  w.density = p.at("rho");
  w.kinematic_viscosity = p.at("nu");
  return w;
}

// wall_rule: the scene's viscous wall velocity, or another (fluid.viscous_wall_velocity) named in the case.
WomersleyRun run_case(const SuiteContext& ctx, double wo, int resolution, SuiteSummary& summary,
                      const std::string& wall_rule = "") {
  const std::string name = fmt::format("Wo={:g} H/dp={}{}", wo, resolution, wall_rule.empty() ? "" : " " + wall_rule + " wall rule");
  if (ctx.log) ctx.log("womersley: " + name);
  WomersleyRun out{wo, resolution, {}, false};
  CsvTable profiles;
  profiles.columns = {"phase", "time", "y", "u_sph", "u_analytic"};

  std::vector<std::string> overrides{fmt::format("parameters.Wo={}", wo), fmt::format("parameters.resolution={}", resolution)};
  if (!wall_rule.empty()) overrides.push_back(fmt::format(R"(fluid.viscous_wall_velocity="{}")", wall_rule));
  SceneRun run = run_scene(ctx, "womersley.json", overrides, [&](const LoadedScene& scene) {
    const WomersleyProfile analytic = profile_from(scene);
    const double period = 2.0 * M_PI / analytic.angular_frequency;
    const double H = analytic.channel_height;
    RunOptions options;
    options.end_time = 2.0 * period;
    for (int k = 0; k < kPhases; ++k) options.sample_times.push_back(period + k * period / kPhases);
    options.on_sample = [&, analytic, period, H](const Simulation& sim) {
      const FluidParticles& f = sim.fluid().particles;
      const double t = sim.time;
      std::vector<double> sum(resolution, 0.0);
      std::vector<int> count(resolution, 0);
      for (std::size_t i = 0; i < f.size(); ++i) {
        const double y = f.pos[i].y();
        const double ua = analytic.velocity(y, t);
        out.error.err2 += (f.vel[i].x() - ua) * (f.vel[i].x() - ua);
        out.error.ref2 += ua * ua;
        out.error.vertical2 += f.vel[i].y() * f.vel[i].y();
        ++out.error.samples;
        const int row = std::clamp(static_cast<int>(std::floor(y / H * resolution)), 0, resolution - 1);
        sum[row] += f.vel[i].x();
        ++count[row];
      }
      const double phase = std::round((t - period) / period * kPhases);
      for (int row = 0; row < resolution; ++row) {
        if (count[row] == 0) continue;
        const double y = (row + 0.5) * H / resolution;
        profiles.add_row({phase, t, y, sum[row] / count[row], analytic.velocity(y, t)});
      }
    };
    return options;
  });
  out.diverged = run.result.divergence.has_value();
  profiles.write(ctx.out_dir / fmt::format("profiles_Wo{:g}_res{}{}.csv", wo, resolution, wall_rule.empty() ? "" : "_" + wall_rule));

  SuiteRun record;
  record.case_name = name;
  record.config = {{"womersley_number", wo}, {"resolution", resolution}, {"dp", run.scene.parameters.at("dp")},
                   {"kinematic_viscosity", run.scene.parameters.at("nu")}, {"phases", kPhases},
                   {"schedule", run.scene.schedule->name()}, {"scene", "womersley.json"},
                   {"viscous_wall_velocity", wall_rule.empty() ? "the scene's" : wall_rule}};
  record.metrics = {{"l2_error", out.error.l2()}, {"vertical_velocity_ratio", out.error.vertical_ratio()},
                    {"samples", out.error.samples}};
  record.cost = cost_json(run);
  record.compressibility = compressibility_record(run);
  record.diverged = out.diverged;
  record.divergence = divergence_record(run);
  summary.add_run(std::move(record));
  return out;
}

}  // namespace

SuiteSummary run_womersley_suite(const SuiteContext& ctx) {
  SuiteSummary summary("womersley", ctx.quick, ctx.threads);
  const std::vector<double> numbers{1.0, 5.0, 10.0};
  // Quick: the CI-sized resolution (H/dp = 20) with the ladder 10-20-40 for the order. Full: the
  // acceptance resolution H/dp = 40 with the ladder 20-40-80.
  const std::vector<int> ladder = ctx.quick ? std::vector<int>{10, 20, 40} : std::vector<int>{20, 40, 80};
  const int checked = ctx.quick ? 20 : 40;
  const std::string source = "issue 2 acceptance: relative L2 error over a period (CASES.md, analytic profile)";

  Json table = Json::array();
  for (double wo : numbers) {
    std::map<int, WomersleyRun> runs;
    for (int res : ladder) runs.emplace(res, run_case(ctx, wo, res, summary));
    // Tolerances: full mode at H/dp = 40, 2 % for Wo = 1 and 5 and 3 % for Wo = 10, whose Stokes
    // layer (H/2) sqrt(2)/Wo is under 3 particles there; quick mode at H/dp = 20, 5 % for each.
    const double tolerance = ctx.quick ? 0.05 : (wo >= 10.0 ? 0.03 : 0.02);
    const WomersleyRun& r = runs.at(checked);
    const std::string check = fmt::format("Wo={:g} l2_error at H/dp={}", wo, checked);
    if (r.diverged) summary.check_missing(check, "the run diverged", source);
    else summary.check_at_most(check, r.error.l2(), tolerance, source);

    // Full mode: the quadratic wall rule (an option) beside the default at the checked resolution.
    // At the wall the profile's curvature is the body force's (nu u'' = -b, the wall at rest), and at
    // Wo = 1 the profile departs from a parabola by 1.4 % over the period (relative L2): that rule
    // continues it into the wall nearly exactly, where the linear one slips by -kappa d_a (d_i + d_a) / 2
    // (fluid/wall_rules.hpp). The slip is most of the default's error (reports/pressure.md section 34:
    // 0.097 -> 0.046 % at H/dp = 40), so the quadratic rule's must stay below three quarters of it.
    if (!ctx.quick) {
      const WomersleyRun quadratic = run_case(ctx, wo, checked, summary, "quadratic");
      if (wo == 1.0) {
        const std::string name = fmt::format("Wo=1 quadratic wall rule against the default at H/dp={} (error ratio)", checked);
        const std::string why = "the linear wall rule's slip is most of Wo = 1's error (reports/pressure.md section 34)";
        if (quadratic.diverged || r.diverged) summary.check_missing(name, "a run diverged", why);
        else summary.check_at_most(name, quadratic.error.l2() / r.error.l2(), 0.75, why);
      }
    }

    Json row = {{"womersley_number", wo}};
    for (const auto& [res, run] : runs) row[fmt::format("l2_error_res{}", res)] = run.error.l2();
    const double e_coarse = runs.at(ladder[1]).error.l2(), e_fine = runs.at(ladder[2]).error.l2();
    row["observed_order"] = order_from_errors(e_coarse, e_fine, 2.0);
    row["observed_order_coarse"] = order_from_errors(runs.at(ladder[0]).error.l2(), e_coarse, 2.0);
    table.push_back(row);
  }
  summary.extra()["convergence"] = table;
  summary.write(ctx.out_dir);
  render_figures(ctx, "plot_womersley.py", summary);
  summary.write(ctx.out_dir);
  return summary;
}

}  // namespace mrsph::verification
