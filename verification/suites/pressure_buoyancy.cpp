// verify --suite pressure: the force of still water on a body, against Archimedes. A cylinder held
// under the surface of a still tank (submerged_cylinder.json, the defaults a new user gets): after
// the column has settled, the water pushes it up with its displaced weight rho g pi R^2, whatever
// the sound speed and the resolution. Over the force observer's samples after settling:
//   buoyancy_ratio  the mean upward force over rho g pi R^2
//   buoyancy_error  (mean force - rho g pi R^2) / (rho g H 2R): the error as a mean pressure error
//                   over the body's projected width, in units of rho g H (the tank's own measure:
//                   the buoyancy is a difference of pressures, half of rho g H apart here)
//   buoyancy_std    the standard deviation in time of the force averaged over each observer
//                   interval, over rho g pi R^2
//   force_balance   (mean force on the tank + mean force on the cylinder + M g) / (M g), M the
//                   water's mass: the fluid's momentum balance as the force observers read it. The
//                   water at rest takes from the walls and the body exactly its weight, so this is
//                   zero but for the fluid's momentum change over the window (below 3.5e-5 in 54
//                   runs of reports/pressure.md section 19); a reading that samples the force at one
//                   phase can break it (the last-step sample there: up to 3.6 %)
#include "suites/pressure_suite.hpp"

#include "suites/scene_run.hpp"

#include <fmt/format.h>

#include <cmath>

namespace mrsph::verification {

namespace {

struct BuoyancyCase {
  int resolution, factor;  // H / dp; c over sqrt(2 g H)
};

std::string case_name(const BuoyancyCase& c) {
  return fmt::format("submerged cylinder H/dp={} c={}sqrt(2gH)", c.resolution, c.factor);
}

SuiteRun run_buoyancy(const SuiteContext& ctx, const BuoyancyCase& c, double settle, double end_time) {
  if (ctx.log) ctx.log("pressure: " + case_name(c));
  double rho_g = 0.0, g = 0.0, H = 0.0, R = 0.0;
  SceneRun run = run_scene(ctx, "submerged_cylinder.json",
                           {fmt::format("parameters.resolution={}", c.resolution),
                            fmt::format("parameters.sound_speed_factor={}", c.factor)},
                           [&](const LoadedScene& scene) {
                             g = scene.parameters.at("g");
                             rho_g = scene.parameters.at("rho") * g;
                             H = scene.parameters.at("H");
                             R = scene.parameters.at("R");
                             RunOptions options;
                             options.end_time = end_time;
                             return options;
                           });
  write_observer_series(run.result.series, ctx.out_dir / fmt::format("buoyancy_res{}_c{}", c.resolution, c.factor));

  SuiteRun r;
  r.case_name = case_name(c);
  const double archimedes = rho_g * M_PI * R * R;
  r.config = {{"resolution", c.resolution}, {"sound_speed_factor", c.factor}, {"settle_time", settle},
              {"end_time", end_time}, {"archimedes_force", archimedes}, {"scene", "submerged_cylinder.json"}};
  r.cost = cost_json(run);
  r.compressibility = compressibility_record(run);
  r.diverged = run.result.divergence.has_value();
  r.divergence = divergence_record(run);
  if (r.diverged) return r;
  // The force observer's columns are fx, fy, fx_viscous, fy_viscous (as run_cylinder reads them).
  const WindowStats up = window_stats(series_named(run.result.series, "cylinder_force"), 1, settle);
  const WindowStats tank = window_stats(series_named(run.result.series, "tank_force"), 1, settle);
  double mass = 0.0;
  for (double m : run.scene.simulation->fluid().particles.mass) mass += m;
  r.metrics = {{"buoyancy_ratio", up.mean / archimedes},
               {"buoyancy_error", (up.mean - archimedes) / (rho_g * H * 2.0 * R)},
               {"buoyancy_std", up.std / archimedes},
               {"force_balance", (tank.mean + up.mean + mass * g) / (mass * g)}};
  return r;
}

}  // namespace

void run_submerged_cylinder(const SuiteContext& ctx, SuiteSummary& summary) {
  // Settling as in the still tank (pressure_fields.cpp): the acoustic breathing is damped within a second.
  const double settle = ctx.quick ? 1.0 : 1.5, end_time = ctx.quick ? 2.0 : 3.0;
  const std::vector<BuoyancyCase> plan = ctx.quick ? std::vector<BuoyancyCase>{{20, 10}}
                                                   : std::vector<BuoyancyCase>{{20, 10}, {40, 10}, {80, 10}, {40, 20}, {40, 30}, {40, 40}};
  std::vector<SuiteRun> records;
  for (const BuoyancyCase& c : plan) records.push_back(run_buoyancy(ctx, c, settle, end_time));
  const std::string source =
      "Archimedes: the displaced weight rho g pi R^2; as a pressure over the projected width, the still tank's tolerances of issue 17";
  // |error| as a pressure over the width 2R, in units of rho g H: 5 % at H/dp = 20 (quick, as the
  // tank's coarse profile), 1 % at H/dp = 40 at each sound speed (the buoyancy cannot depend on c).
  const auto check = [&](std::size_t k, double limit) {
    const double error = run_metric(records[k], "buoyancy_error");
    check_at_most_or_missing(summary, records[k].case_name + ": buoyancy error as a pressure over 2R (of rho g H)",
                             std::abs(error), limit, source);
  };
  // The water's momentum balance as the forces are read: 0.1 % of its weight, 30 times what the
  // interval averages leave (3.5e-5); the biased reading broke it in 10 of 30 runs, by up to 3.6 %.
  for (const SuiteRun& r : records)
    check_at_most_or_missing(summary, r.case_name + ": forces on tank and body against the water's weight",
                             std::abs(run_metric(r, "force_balance")), 0.001,
                             "momentum: water at rest takes its weight from its walls and the body");
  if (ctx.quick) {
    check(0, 0.05);
  } else {
    // c = 10, 20, 30 and 40 sqrt(2 g H) (reports/pressure.md section 19: with the force averaged over
    // the observer interval, -0.4 to +1.8 % of Archimedes over six output intervals at c = 10-40).
    for (std::size_t k : {std::size_t(1), std::size_t(3), std::size_t(4), std::size_t(5)}) check(k, 0.01);
  }
  for (SuiteRun& r : records) summary.add_run(std::move(r));
}

}  // namespace mrsph::verification
