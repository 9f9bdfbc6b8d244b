#include "scene/scene_loader.hpp"

#include "boundary/initial_velocity.hpp"
#include "neighbor/cell_grid.hpp"
#include "scene/body_reader.hpp"
#include "scene/open_boundary_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace mrsph {

namespace {

ParameterTable read_parameters(const Json& document, const std::string& file) {
  ParameterTable table;
  if (!document.contains("parameters")) return table;
  const Json& params = document.at("parameters");
  if (!params.is_object()) throw InputError(file, "parameters", "expected an object of name: value, got " + describe_json(params));
  // In order of appearance: a parameter may use the ones defined before it.
  for (auto it = params.begin(); it != params.end(); ++it) {
    const std::string key = "parameters." + it.key();
    double value = 0.0;
    if (it.value().is_number()) {
      value = it.value().get<double>();
    } else if (it.value().is_string()) {
      try {
        value = evaluate_expression(it.value().get<std::string>(), table);
      } catch (const ExpressionError& e) {
        throw InputError(file, key, e.what());
      }
    } else {
      throw InputError(file, key, "expected a number or an expression string, got " + describe_json(it.value()));
    }
    if (!std::isfinite(value)) throw InputError(file, key, "evaluates to a non-finite number");
    table[it.key()] = value;
  }
  return table;
}

DomainBox read_domain(const SceneNode& node) {
  DomainBox box;
  box.lower = node.vec2("lower");
  box.upper = node.vec2("upper");
  box.periodic = node.flag_pair_or("periodic", {false, false});
  if (!(box.upper.x() > box.lower.x() && box.upper.y() > box.lower.y()))
    node.fail("upper", "the upper corner must lie above and to the right of the lower corner");
  if (!(box.upper - box.lower).allFinite())
    node.fail("upper", "the domain's extent overflows: the corners must lie within a finite distance of each other");
  node.finish();
  return box;
}


struct PlacedBody {
  std::string name;
  ShapePtr region;
  Real dp;
  const Vec2Array* pos;
};


void check_overlaps(const std::vector<PlacedBody>& bodies, const std::string& file) {
  for (const PlacedBody& a : bodies)
    for (const PlacedBody& b : bodies) {
      if (&a == &b) continue;
      for (const Vec2& p : *a.pos)
        if (b.region->signed_distance(p) < -0.25 * b.dp)
          throw InputError(file, "", fmt::format("bodies '{}' and '{}' overlap: a particle of '{}' at ({:g}, {:g}) lies "
                                                 "inside the region of '{}' (cut one region out of the other)",
                                                 a.name, b.name, a.name, p.x(), p.y(), b.name));
    }
}

// A body whose lattice crosses a periodic boundary continues through it only if the periodic length
// is a whole number of its spacings; otherwise the seam leaves a gap or an overlap in the lattice
// (FSI2 at ratio 3: 13 / 0.15 = 86.67 fluid spacings, a gap in the walls, diverged at t = 2.97).
void check_periodic_seams(const std::vector<PlacedBody>& bodies, const DomainBox& box, const std::string& file) {
  for (int a = 0; a < 2; ++a) {
    if (!box.periodic[a]) continue;
    for (const PlacedBody& body : bodies) {
      if (body.pos->empty()) continue;
      Real low = box.upper[a], high = box.lower[a];
      for (const Vec2& p : *body.pos) { low = std::min(low, p[a]); high = std::max(high, p[a]); }
      // A lattice that fills the whole length ends between dp/2 and 3 dp/2 short of the upper side.
      const bool crosses = low < box.lower[a] + body.dp && high > box.upper[a] - 2.0 * body.dp;
      const Real spacings = box.length(a) / body.dp;
      const Real whole = std::round(spacings);
      if (crosses && std::abs(spacings - whole) > 1e-6 * spacings)
        throw InputError(file, "domain", fmt::format(
            "the periodic length along {} is {:g}, which is {:.4f} spacings of body '{}' (dp = {:g}); a body that "
            "crosses the periodic boundary needs a whole number of spacings, or its lattice has a gap or an overlap "
            "at the seam: use dp = {:.6g} ({:g} spacings) or {:.6g} ({:g} spacings), or change the length",
            a == 0 ? "x" : "y", box.length(a), spacings, body.name, body.dp, box.length(a) / std::max(1.0, std::floor(spacings)),
            std::max(1.0, std::floor(spacings)), box.length(a) / std::ceil(spacings), std::ceil(spacings)));
    }
  }
}

ObservedQuantity read_quantity(const SceneNode& node) {
  const std::string q = node.choice("quantity", {"position", "displacement", "velocity", "pressure", "force", "front", "gap"});
  if (q == "position") return ObservedQuantity::Position;
  if (q == "displacement") return ObservedQuantity::Displacement;
  if (q == "velocity") return ObservedQuantity::Velocity;
  if (q == "pressure") return ObservedQuantity::Pressure;
  if (q == "front") return ObservedQuantity::Front;
  if (q == "gap") return ObservedQuantity::Gap;
  return ObservedQuantity::Force;
}


// The fluid, walls and solids, in that order (their regions too, for the placement checks), then
// the contacts between them.
void read_bodies(const SceneNode& root, Simulation& sim, const DomainBox& box, double budget,
                 std::vector<ShapePtr>& regions, InitialVelocity& fluid_velocity) {
  if (const auto node = root.optional_child("fluid")) {
    ShapePtr region;
    sim.set_fluid(read_fluid(*node, box, budget, region, fluid_velocity));
    regions.push_back(region);
  }
  for (const SceneNode& node : root.children("walls")) {
    ShapePtr region;
    sim.add_wall(read_wall(node, box, budget, region));
    regions.push_back(region);
  }
  for (const SceneNode& node : root.children("solids")) {
    ShapePtr region;
    SolidBody& solid = sim.add_solid(read_solid(node, box, budget, region));
    regions.push_back(region);
    if (sim.has_fluid() && sim.fluid().h() < solid.h() * (1.0 - 1e-12))
      node.fail("dp", fmt::format("the method needs h_F >= h_S (paper section 3.1): fluid h = {:g} but solid '{}' has "
                                  "h = {:g}; refine the solid or coarsen the fluid",
                                  sim.fluid().h(), solid.name, solid.h()));
  }
  if (!sim.has_fluid() && sim.solids().empty())
    root.fail("", "the scene has neither a fluid nor a solid body: nothing to simulate");
  for (const SceneNode& node : root.children("solid_contacts")) sim.solid_contacts.push_back(read_solid_contact(node, sim));
}

// A periodic axis must hold three kernel supports, or the cell list would see a particle twice, and
// at most CellGrid::kMaxPeriodicCells of them, or its cell count would not fit the grid's index.
void check_periodic_reach(const SceneNode& root, const Simulation& sim, const DomainBox& box) {
  Real reach = 0.0;
  if (sim.has_fluid()) reach = sim.fluid().kernel.cutoff();
  for (const auto& w : sim.walls()) reach = std::max(reach, w.kernel.cutoff());
  for (const auto& s : sim.solids()) reach = std::max(reach, s.kernel.cutoff());
  for (int a = 0; a < 2; ++a) {
    if (!box.periodic[a]) continue;
    const char* axis = a == 0 ? "x" : "y";
    if (box.length(a) < 3.0 * reach)
      root.fail("domain", fmt::format("the periodic length along {} is {:g}, but it must be at least three kernel supports "
                                      "(3 x {:g} = {:g}): lengthen the domain or refine the particles",
                                      axis, box.length(a), reach, 3.0 * reach));
    if (reach > 0.0 && !(box.length(a) / reach <= CellGrid::kMaxPeriodicCells))
      root.fail("domain", fmt::format("the periodic length along {} is {:g}, which is more than {:g} kernel supports "
                                      "({:g}): the cell list cannot divide it; shorten the domain",
                                      axis, box.length(a), CellGrid::kMaxPeriodicCells, reach));
  }
}

// Names must be unique: observers and reports refer to bodies by name.
void check_unique_names(const SceneNode& root, const Simulation& sim) {
  std::vector<std::string> names;
  if (sim.has_fluid()) names.push_back(sim.fluid().name);
  for (const auto& w : sim.walls()) names.push_back(w.name);
  for (const auto& s : sim.solids()) names.push_back(s.name);
  for (std::size_t i = 0; i < names.size(); ++i)
    for (std::size_t j = i + 1; j < names.size(); ++j)
      if (names[i] == names[j]) root.fail("", "two bodies are named '" + names[i] + "'; body names must be unique");
}

// No body inside another, none across a periodic seam; regions in the order of read_bodies.
void check_placement(const Simulation& sim, const std::vector<ShapePtr>& regions, const DomainBox& box,
                     const std::string& file) {
  std::vector<PlacedBody> placed;
  std::size_t r = 0;
  if (sim.has_fluid()) placed.push_back({sim.fluid().name, regions[r++], sim.fluid().dp, &sim.fluid().particles.pos});
  for (const auto& w : sim.walls()) placed.push_back({w.name, regions[r++], w.dp, &w.particles.pos});
  for (const auto& s : sim.solids()) placed.push_back({s.name, regions[r++], s.dp, &s.particles.pos0});
  check_overlaps(placed, file);
  check_periodic_seams(placed, box, file);
}

// What drives the flow: a body force, a periodic channel's inflow buffer, open boundaries.
void read_driving(const SceneNode& root, Simulation& sim) {
  if (const auto node = root.optional_child("body_force")) {
    sim.body_force.constant = node->vec2_or("constant", Vec2::Zero());
    sim.body_force.amplitude = node->vec2_or("amplitude", Vec2::Zero());
    sim.body_force.angular_frequency = node->non_negative_or("angular_frequency", 0.0);
    sim.body_force.phase = node->number_or("phase", 0.0);
    sim.body_force_on_solids = node->flag_or("on_solids", true);
    node->finish();
  }
  if (const auto node = root.optional_child("inflow")) {
    if (!sim.has_fluid()) node->fail("", "an inflow needs a fluid body");
    sim.inflow = read_inflow(*node);
  }
  sim.open_boundaries = read_open_boundaries(root, sim);
}

std::unique_ptr<Schedule> read_schedule(const SceneNode& root, Simulation& sim) {
  std::string schedule_name = "multi_step_position_verlet";
  AcousticSteps acoustic_steps = AcousticSteps::EqualSplit;  // performance.md sections 3, 13 and 19
  if (const auto node = root.optional_child("schedule")) {
    schedule_name = node->choice_or(
        "type", {"multi_step_position_verlet", "single_step_position_verlet", "multi_step_velocity_verlet"}, schedule_name);
    const std::string kinematics = node->choice_or(
        "solid_kinematics", {"averaged", "averaged_second_difference", "instantaneous"}, "averaged");
    sim.solid_kinematics = kinematics == "instantaneous"                ? SolidKinematics::Instantaneous
                           : kinematics == "averaged_second_difference" ? SolidKinematics::AveragedSecondDifference
                                                                        : SolidKinematics::Averaged;
    const std::string steps =
        node->choice_or("acoustic_steps", {"equal_split", "full_steps", "full_steps_inside"}, "equal_split");
    acoustic_steps = steps == "full_steps"          ? AcousticSteps::FullSteps
                     : steps == "full_steps_inside" ? AcousticSteps::FullStepsInside
                                                    : AcousticSteps::EqualSplit;
    if (acoustic_steps != AcousticSteps::EqualSplit && schedule_name == "multi_step_velocity_verlet")
      node->fail("acoustic_steps", steps + " is an option of the position-based Verlet schedules; "
                                   "expected equal_split with multi_step_velocity_verlet");
    node->finish();
  }
  if (schedule_name == "multi_step_velocity_verlet" && !sim.solid_contacts.empty())
    root.fail("solid_contacts", "solid contacts are integrated by the position-based Verlet schedules only; "
                                "choose multi_step_position_verlet or single_step_position_verlet");
  return make_schedule(schedule_name, acoustic_steps);
}

// Divergence limits, end time and output intervals.
void read_run_settings(const SceneNode& root, Simulation& sim, SceneRunSettings& run) {
  if (const auto node = root.optional_child("limits")) {
    sim.limits.speed_factor = node->positive_or("speed_factor", sim.limits.speed_factor);
    node->finish();
  }
  run.end_time = root.positive("end_time");
  if (const auto node = root.optional_child("output")) {
    run.observer_interval = node->non_negative_or("observer_interval", 0.0);
    run.snapshot_interval = node->non_negative_or("snapshot_interval", 0.0);
    node->finish();
  }
}

ObserverSpec read_observer(const SceneNode& node) {
  ObserverSpec spec;
  spec.name = node.text("name");
  spec.quantity = read_quantity(node);
  if (node.has("bodies")) {
    const Json& list = node.raw().at("bodies");
    if (!list.is_array() || list.empty()) node.fail("bodies", "expected a non-empty array of body names");
    for (const Json& b : list) {
      if (!b.is_string()) node.fail("bodies", "expected body names (strings), got " + describe_json(b));
      spec.bodies.push_back(b.get<std::string>());
    }
  } else {
    spec.bodies.push_back(node.text("body"));
  }
  if (spec.quantity == ObservedQuantity::Front) spec.direction = node.vec2_or("direction", spec.direction);
  else if (spec.quantity != ObservedQuantity::Force && spec.quantity != ObservedQuantity::Gap) spec.point = node.vec2("point");
  spec.nearest_particle = node.flag_or("nearest_particle", false);
  node.finish();
  return spec;
}

// Initialises the simulation, gives a relaxed fluid its initial velocity at the moved positions, and
// checks that every observer finds what it observes.
void finish_simulation(Simulation& sim, const InitialVelocity& fluid_velocity, const std::vector<ObserverSpec>& observers,
                       const std::string& file) {
  sim.initialise();
  if (sim.has_fluid() && (sim.fluid().options.relaxation_steps > 0 || sim.fluid().options.relaxation_perturbation > 0.0)) {
    FluidParticles& f = sim.fluid().particles;
    for (std::size_t i = 0; i < f.size(); ++i) f.vel[i] = initial_velocity_at(fluid_velocity, f.pos[i]);
  }
  for (const ObserverSpec& spec : observers) {
    try {
      PointObserver probe(spec, sim);
    } catch (const std::invalid_argument& e) {
      throw InputError(file, "observers", e.what());
    }
  }
}

}  // namespace

LoadedScene build_scene(const Json& document, const std::string& file, const SceneLimits& limits) {
  auto context = std::make_shared<SceneContext>();
  context->file = file;
  context->parameters = read_parameters(document, file);
  const SceneNode root(document, context, "");
  root.has("parameters");  // read above

  LoadedScene scene;
  scene.file = file;
  scene.document = document;
  scene.parameters = context->parameters;
  scene.name = root.has("name") ? root.text("name") : std::filesystem::path(file).stem().string();
  scene.description = root.has("description") ? root.text("description") : "";
  scene.units = root.has("units") ? root.text("units") : "";

  const DomainBox box = read_domain(root.child("domain"));
  auto sim = std::make_unique<Simulation>(box);
  std::vector<ShapePtr> regions;
  InitialVelocity fluid_velocity;
  read_bodies(root, *sim, box, limits.max_particles, regions, fluid_velocity);
  check_periodic_reach(root, *sim, box);
  check_unique_names(root, *sim);
  check_placement(*sim, regions, box, file);
  read_driving(root, *sim);
  scene.schedule = read_schedule(root, *sim);
  read_run_settings(root, *sim, scene.run);
  for (const SceneNode& node : root.children("observers")) scene.observers.push_back(read_observer(node));
  root.finish();

  finish_simulation(*sim, fluid_velocity, scene.observers, file);
  scene.simulation = std::move(sim);
  return scene;
}

LoadedScene load_scene(const std::filesystem::path& path, const std::vector<std::string>& overrides,
                       const SceneLimits& limits) {
  Json document = read_scene_document(path);
  for (const std::string& o : overrides) apply_override(document, o, path.string());
  return build_scene(document, path.string(), limits);
}

}  // namespace mrsph
