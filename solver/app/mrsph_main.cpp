// mrsph: runs any scene file. See `mrsph --help`.
#include "core/thread_limit.hpp"
#include "fluid/density_summation.hpp"
#include "fluid/transport_velocity.hpp"
#include "io/atomic_file.hpp"
#include "scene/scene_loader.hpp"
#include "run/checkpoint.hpp"
#include "run/run_summary.hpp"
#include "run/runner.hpp"
#include "solid/solid_dynamics.hpp"
#include "solid/step_criterion.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <tbb/info.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>
#include <unistd.h>

namespace {

constexpr int kExitInputError = 1;
constexpr int kExitDiverged = 2;
constexpr int kExitFailure = 3;
constexpr int kExitInterrupted = 4;

// Set by SIGINT/SIGTERM; the run stops at the end of the current advection step, writes a
// checkpoint and a summary marked incomplete. (The one piece of global state: a signal handler
// can reach nothing else.)
std::atomic<bool> g_stop_requested{false};
extern "C" void request_stop(int) { g_stop_requested.store(true); }

// How the viscous force continues the velocity into the walls.
const char* viscous_wall_velocity_description(mrsph::ViscousWallVelocity rule) {
  switch (rule) {
    case mrsph::ViscousWallVelocity::Mirrored: return "mirrored (the paper's)";
    case mrsph::ViscousWallVelocity::Quadratic: return "continued as a parabola (the wall's momentum balance)";
    default: return "continued linearly into the wall";
  }
}

// When the acoustic passes evaluate their pairs' geometry: the pressure pass's and the continuity pass's.
std::string pair_geometry_description(const mrsph::FluidOptions& o) {
  const auto when = [](bool refreshed) { return refreshed ? "at each acoustic step" : "cached per advection step"; };
  return fmt::format("in the pressure pass {}, in the continuity pass {}", when(o.refresh_pair_geometry),
                     when(o.refresh_divergence_geometry));
}

// Where a once-per-step coefficient was scaled by FluidOptions::paper_step_fraction(), the option's
// value and the scaling; else nothing.
std::string cfl_scaling_note(mrsph::Real per_step, mrsph::Real option, const mrsph::FluidOptions& o) {
  if (per_step == option) return "";
  return fmt::format(" ({:g} scaled by the advection CFL {:g} / {:g})", option, o.advection_cfl, mrsph::kPaperAdvectionCfl);
}

// The transport-velocity shift's coefficient per advection step, and alpha where the CFL scaled it.
std::string transport_shift_description(const mrsph::FluidOptions& o) {
  if (o.transport_velocity_alpha == 0.0) return "off";
  const mrsph::Real per_step = mrsph::shift_alpha_per_step(o);
  return fmt::format("alpha {:g} per advection step{}", per_step, cfl_scaling_note(per_step, o.transport_velocity_alpha, o));
}

// The summation's relaxation per advection step, and the option's where the CFL scaled it.
std::string density_reset_description(const mrsph::FluidOptions& o) {
  const mrsph::Real per_step = mrsph::density_relaxation_per_step(o);
  if (per_step == 1.0) return "summation each advection step";
  return fmt::format("summation each advection step, relaxed by {:g}{}", per_step,
                     cfl_scaling_note(per_step, o.density_relaxation, o));
}

// What the fluid's pressure forces are measured from, divided by and continued into the walls with.
std::string pressure_forces_description(const mrsph::Simulation& sim) {
  const auto& f = sim.fluid();
  const auto reference = f.options.pressure_reference;
  std::string s = reference == mrsph::PressureReference::Mean     ? "the mean pressure"
                  : reference == mrsph::PressureReference::Linear ? "a linear fit of the pressure, its gradient applied exactly"
                                                                  : "zero";
  if (f.options.pressure_gradient_correction)
    s += ", each side with its kernel-gradient correction";
  else if (f.options.pressure_lattice_correction)
    s += f.options.measured_pressure_moment ? ", divided by the arrangement's measured moment" : ", divided by the lattice moment";
  if (f.options.rest_state_at_walls && !f.riemann.rest_pressure_gradient(sim.body_force.constant).isZero())
    s += ", the rest state continued into the walls";
  return s;
}

void print_schedule(const mrsph::LoadedScene& scene) {
  const mrsph::Simulation& sim = *scene.simulation;
  fmt::print("schedule   {}   end time {:g}", scene.schedule->name(), scene.run.end_time);
  if (sim.has_fluid() && std::isfinite(sim.fluid().options.max_advection_step))
    fmt::print("   advection step at most {:g}", sim.fluid().options.max_advection_step);
  fmt::print("\n");
}

void print_scene(const mrsph::LoadedScene& scene) {
  const mrsph::Simulation& sim = *scene.simulation;
  fmt::print("scene      {} ({})\n", scene.name, scene.file);
  if (!scene.description.empty()) fmt::print("           {}\n", scene.description);
  if (!scene.units.empty()) fmt::print("units      {}\n", scene.units);
  if (sim.has_fluid()) {
    const auto& f = sim.fluid();
    fmt::print("fluid      {:<12} {:>8} particles  dp {:g}  h {:g}  c {:g}  mu {:g}\n", f.name, f.particles.size(), f.dp,
               f.h(), f.material.sound_speed(), f.material.viscosity);
    const bool free_surface = f.options.density == mrsph::DensityReinitialisation::FreeSurface;
    const bool continuity = f.options.density == mrsph::DensityReinitialisation::None;
    fmt::print("           {} fluid: density by {}; pressure forces from {}; Riemann dissipation in continuity {}, in"
               " momentum {}; delta-SPH diffusion {}; pair geometry {}; viscous wall velocity {};"
               " continuity's wall velocity {}; transport-velocity shift {}; emptiest kernel support {:.0f} % filled\n",
               free_surface ? "free-surface" : sim.open_boundaries.empty() ? "confined" : "open (inlet/outlet)",
               continuity                               ? std::string("the continuity equation")
                                                        : density_reset_description(f.options),
               pressure_forces_description(sim),
               !f.riemann.continuity ? "off"
               : f.riemann.rest_pressure_gradient(sim.body_force.constant).isZero() ? "on"
                                                                                    : "on, hydrostatically balanced",
               f.riemann.momentum ? "on" : "off",
               f.options.delta_sph > 0.0 ? fmt::format("delta {:g}", f.options.delta_sph) : std::string("off"),
               pair_geometry_description(f.options),
               viscous_wall_velocity_description(f.options.viscous_wall_velocity),
               f.options.mirrored_wall_continuity ? "mirrored (the paper's)" : "the boundary's (the summation's derivative)",
               transport_shift_description(f.options),
               100.0 * mrsph::smallest_support_fraction(f, sim.fluid_inner(), sim.fluid_contacts()));
  }
  for (const auto& b : sim.open_boundaries)
    fmt::print("open       {:<12} {} {} = {:g}, buffer {:g} deep, {} condition{}\n", b.name, b.side > 0 ? "upper" : "lower",
               b.axis == 0 ? "x" : "y", b.plane, b.width,
               b.condition == mrsph::OpenBoundaryCondition::Velocity ? "velocity"
               : b.reflection_time > 0.0 ? fmt::format("weakly reflecting pressure (tau {:g})", b.reflection_time)
                                         : std::string("pressure"),
               std::string(b.total_pressure_inflow ? ", total pressure where fluid enters" : "") +
                   (b.smooth_normal_velocity ? ", normal velocity smoothed along the plane" : ""));
  for (const auto& w : sim.walls())
    fmt::print("wall       {:<12} {:>8} particles  dp {:g}  h {:g}\n", w.name, w.particles.size(), w.dp, w.h());
  for (const auto& s : sim.solids()) {
    std::size_t clamped = 0;
    for (auto c : s.particles.constrained) clamped += c;
    fmt::print("solid      {:<12} {:>8} particles  dp {:g}  h {:g}  {}  E {:g}  nu {:g}  c_S {:g}  clamped {}\n", s.name,
               s.particles.size(), s.dp, s.h(), s.material.model_name(), s.material.youngs_modulus(),
               s.material.poisson_ratio(), s.material.sound_speed(), clamped);
    const mrsph::Real step = mrsph::solid_time_step(s);
    fmt::print("           step {:.4g} (the criterion's 0.6 h / c_S times {:.3f} for its gradient weights)", step,
               s.weights.time_step_scale);
    if (s.weights.highest_frequency > 0.0)
      fmt::print("; omega_max dt = {:.3f} (position Verlet is stable below 2)", s.weights.highest_frequency * step);
    if (s.weights.highest_damping_rate > 0.0)
      fmt::print("; damping's rate dt = {:.3f} (at most {:g})", s.weights.highest_damping_rate * step,
                 mrsph::kDampingStepLimit);
    fmt::print("\n");
  }
  print_schedule(scene);
}

std::string duration_text(double s) {
  if (s < 60) return fmt::format("{:.0f} s", s);
  if (s < 3600) return fmt::format("{:.0f} min {:02.0f} s", std::floor(s / 60), std::fmod(s, 60));
  return fmt::format("{:.0f} h {:02.0f} min", std::floor(s / 3600), std::fmod(s / 60, 60));
}

// What the command line asked for.
struct CommandLine {
  bool restarting = false, checking = false;
  std::string scene_path, checkpoint_file;
  std::vector<std::string> overrides;
  std::string out_dir;
  int threads = 0;
  double snapshot_interval = -1.0, end_time = -1.0, max_particles = 2.0e7;
  double checkpoint_every = 0.0, checkpoint_minutes = 0.0;
  bool quiet = false;
};

// The scene of `run` and `check`, or the scene and state of a checkpoint for `restart`.
mrsph::LoadedScene load_for_command(const CommandLine& cli, mrsph::RunnerState& resume_state) {
  mrsph::SceneLimits limits;
  limits.max_particles = cli.max_particles;
  if (!cli.restarting) return mrsph::load_scene(cli.scene_path, cli.overrides, limits);
  const mrsph::CheckpointHeader header = mrsph::read_checkpoint_header(cli.checkpoint_file);
  mrsph::LoadedScene scene = mrsph::build_scene(header.scene_document, header.scene_file, limits);
  for (const auto& spec : scene.observers)
    resume_state.series.push_back(mrsph::ObserverSeries{spec.name, mrsph::PointObserver(spec, *scene.simulation).columns(), {}, {}});
  mrsph::restore_checkpoint(cli.checkpoint_file, *scene.simulation, resume_state);
  return scene;
}

// Outputs, checkpoints and the stop request of a run into `out`.
mrsph::RunOptions run_options(const CommandLine& cli, const mrsph::LoadedScene& scene, const std::filesystem::path& out) {
  mrsph::RunOptions options;
  options.end_time = scene.run.end_time;
  options.observer_interval = scene.run.observer_interval;
  options.snapshot_interval = scene.run.snapshot_interval;
  options.snapshot_dir = out / "snapshots";
  options.scene_document = &scene.document;
  options.scene_file = scene.file;
  options.checkpoint_path = out / "checkpoint.bin";
  options.checkpoint_interval = cli.checkpoint_every;
  options.checkpoint_wall_interval_s = 60.0 * cli.checkpoint_minutes;
  options.last_good_path = out / "last_good.bin";
  options.stop_requested = &g_stop_requested;
  return options;
}

// A progress line on stderr: rewritten in place on a terminal, a line every 10 s otherwise.
void add_progress_line(mrsph::RunOptions& options, bool terminal, std::size_t particles) {
  options.progress_interval_s = terminal ? 0.5 : 10.0;
  options.on_progress = [terminal, particles](const mrsph::RunProgress& p) {
    const double fraction = p.time / p.end_time;
    const double eta = fraction > 0 ? p.wall_s * (1.0 - fraction) / fraction : 0.0;
    const double updates = static_cast<double>(p.steps.acoustic) * static_cast<double>(particles) / p.wall_s;
    fmt::print(stderr, "{}t = {:.4g} / {:g} ({:.1f}%)  steps: {} adv, {} ac, {} solid  {:.3g} particle-steps/s  ETA {}{}",
               terminal ? "\r" : "", p.time, p.end_time, 100.0 * fraction, p.steps.advection, p.steps.acoustic,
               p.steps.solid, updates, duration_text(eta), terminal ? "   " : "\n");
    std::fflush(stderr);
  };
}

// A completed run whose fluid went faster than this Mach number is reported with a warning (exit 0):
// its density then errs by about Mach^2 / 2 = 12 % or more, beyond the weak compressibility the
// method assumes (compressibility_monitor.hpp), without running away. The beam of FSI2 in still water
// at c = 80 U0 did that: an instability saturating at Mach 0.5-1 (reports/pressure.md section 22.1).
constexpr double kMachWarning = 0.5;

// The outcome on the console and as the exit status.
int report_result(const mrsph::RunResult& result, const std::filesystem::path& out, bool quiet) {
  if (result.divergence) {
    fmt::print(stderr, "error: {}\n", mrsph::DivergenceError::describe(*result.divergence));
    fmt::print(stderr, "the last good state (<= 10 advection steps earlier) is in {}; outputs up to it in {}\n",
               result.last_good_written.string(), out.string());
    return kExitDiverged;
  }
  if (result.interrupted) {
    fmt::print(stderr, "interrupted at t = {:g}: checkpoint {} (continue with: mrsph restart {})\n",
               result.end_time_reached, result.checkpoint_written.string(), result.checkpoint_written.string());
    return kExitInterrupted;
  }
  const mrsph::FluidExtreme& mach = result.compressibility.mach;
  if (mach.value > kMachWarning)
    fmt::print(stderr,
               "warning: the fluid reached Mach {:.2f} at t = {:g}, ({:g}, {:g}), above {:g}: the run left the weakly "
               "compressible regime there (density errors near Mach^2 / 2): a sound speed too small for the flow, or an "
               "instability (summary.json: compressibility)\n",
               mach.value, mach.time, mach.position.x(), mach.position.y(), kMachWarning);
  if (!quiet)
    fmt::print("done: t = {:g} in {:.2f} s wall ({:.2f} s CPU), {} advection / {} acoustic / {} solid steps -> {}\n",
               result.end_time_reached, result.wall_s, result.cpu_s, result.steps.advection, result.steps.acoustic,
               result.steps.solid, out.string());
  return 0;
}

// `run`, `restart` or `check`; bad input and other failures become their exit statuses.
int execute(const CommandLine& cli, int used_threads) {
  try {
    mrsph::RunnerState resume_state;
    mrsph::LoadedScene scene = load_for_command(cli, resume_state);
    if (cli.checking) {
      print_scene(scene);
      fmt::print("scene is valid\n");
      return 0;
    }
    if (cli.end_time > 0.0) scene.run.end_time = cli.end_time;
    if (cli.snapshot_interval >= 0.0) scene.run.snapshot_interval = cli.snapshot_interval;
    const std::filesystem::path out =
        cli.out_dir.empty() ? std::filesystem::path("mrsph-out") / scene.name : std::filesystem::path(cli.out_dir);
    std::filesystem::create_directories(out);
    if (!cli.quiet) {
      print_scene(scene);
      if (cli.restarting) fmt::print("restart    from {} at t = {:g}\n", cli.checkpoint_file, scene.simulation->time);
    }
    mrsph::RunOptions options = run_options(cli, scene, out);
    if (cli.restarting) options.resume = &resume_state;
    std::signal(SIGINT, request_stop);
    std::signal(SIGTERM, request_stop);
    const bool terminal = ::isatty(::fileno(stderr));
    if (!cli.quiet) add_progress_line(options, terminal, scene.simulation->particle_count());
    const mrsph::RunResult result = mrsph::run_simulation(*scene.simulation, *scene.schedule, scene.observers, options);
    if (!cli.quiet && terminal) fmt::print(stderr, "\n");
    mrsph::write_observer_series(result.series, out / "observers");
    mrsph::write_file_atomically(out / "summary.json", mrsph::run_summary_json(scene, result, used_threads).dump(2) + "\n");
    return report_result(result, out, cli.quiet);
  } catch (const mrsph::InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitInputError;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitFailure;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "mrsph: multi-resolution SPH for fluid-structure interaction (Zhang, Rezavand & Hu).\n"
      "Runs a JSON scene file (see verification/scenes/README.md) and writes observer CSVs, a JSON\n"
      "summary and, on request, VTP snapshots for ParaView.\n\n"
      "Exit status: 0 run completed; 1 bad input (the message names file, key and what was expected);\n"
      "2 the simulation diverged (time, step, body and particle are reported; the last good state is kept);\n"
      "3 other failure; 4 interrupted by SIGINT/SIGTERM (a checkpoint is written: continue with mrsph restart)."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "mrsph 0.1.0");

  CommandLine cli;
  auto add_scene_options = [&](CLI::App* cmd) {
    cmd->add_option("scene", cli.scene_path, "scene file (JSON)")->required()->check(CLI::ExistingFile);
    cmd->add_option("--set", cli.overrides,
                    "override a value before the scene is built: path=value, e.g. --set fluid.dp=0.05 "
                    "--set parameters.resolution=80 --set 'solids[0].material.youngs_modulus=500'")
        ->take_all();
    cmd->add_option("--max-particles", cli.max_particles, "refuse scenes needing more particles than this (default 2e7)");
  };
  auto add_run_options = [&](CLI::App* cmd) {
    cmd->add_option("--out", cli.out_dir, "output directory (default: mrsph-out/<scene name>)");
    cmd->add_option("--threads", cli.threads, "worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
    cmd->add_option("--snapshots", cli.snapshot_interval, "write VTP snapshots every this much simulated time (0: none)");
    cmd->add_option("--end-time", cli.end_time, "stop at this time instead of the scene's end_time");
    cmd->add_option("--checkpoint-every", cli.checkpoint_every,
                    "write OUT/checkpoint.bin every this much simulated time (0: only when interrupted)");
    cmd->add_option("--checkpoint-minutes", cli.checkpoint_minutes, "write OUT/checkpoint.bin every this many wall-clock minutes");
    cmd->add_flag("--quiet", cli.quiet, "no progress line");
  };
  CLI::App* run = app.add_subcommand("run", "run a scene to its end time");
  add_scene_options(run);
  add_run_options(run);
  CLI::App* restart = app.add_subcommand("restart", "continue a run from a checkpoint (same results as not stopping)");
  restart->add_option("checkpoint", cli.checkpoint_file, "checkpoint file written by mrsph run")->required()->check(CLI::ExistingFile);
  add_run_options(restart);
  CLI::App* check = app.add_subcommand("check", "load a scene, validate it and print its bodies, without running");
  add_scene_options(check);

  CLI11_PARSE(app, argc, argv);
  cli.restarting = restart->parsed();
  cli.checking = check->parsed();
  const int used_threads = cli.threads > 0 ? cli.threads : tbb::info::default_concurrency();
  return mrsph::run_with_threads(used_threads, [&]() -> int { return execute(cli, used_threads); });
}
