#include "scene/scene_loader.hpp"

#include "boundary/initial_velocity.hpp"
#include "scene/initial_velocity_reader.hpp"
#include "scene/open_boundary_reader.hpp"
#include "scene/region_reader.hpp"

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
  node.finish();
  return box;
}

// Particle generation with the checks every body needs.
GeneratedParticles generate_body(const SceneNode& node, const std::string& body, const Shape& region, Real dp,
                                 const FillSpec& fill, const DomainBox& box, double& budget) {
  const double capacity = fill.pattern == FillPattern::Lattice ? lattice_capacity(region, dp)
                                                                : kPi * fill.ring_radius * fill.ring_radius / (dp * dp) * 1.2 + 10;
  if (capacity > budget)
    node.fail("dp", fmt::format("body '{}' would need up to {:.3g} particles at dp = {:g}, more than the {:.3g} still "
                                "allowed (the limit guards memory; raise it with --max-particles)",
                                body, capacity, dp, budget));
  GeneratedParticles generated = generate_particles(region, dp, fill);
  budget -= static_cast<double>(generated.pos.size());
  if (generated.pos.empty())
    node.fail("region", fmt::format("body '{}' has no particles: its region is empty or thinner than dp = {:g}", body, dp));
  for (const Vec2& p : generated.pos) {
    bool inside = box.contains(p);
    for (int a = 0; a < 2; ++a)
      if (box.periodic[a] && (p[a] < box.lower[a] || p[a] >= box.upper[a])) inside = false;
    if (!inside)
      node.fail("region", fmt::format("body '{}' has a particle at ({:g}, {:g}), outside the domain [{:g}, {:g}] x [{:g}, {:g}]",
                                      body, p.x(), p.y(), box.lower.x(), box.upper.x(), box.lower.y(), box.upper.y()));
  }
  return generated;
}

Real read_h_over_dp(const SceneNode& node, Real fallback) {
  if (!node.has("h_over_dp")) return fallback;
  const Real r = node.number("h_over_dp");
  if (!(r >= 0.8 && r <= 3.0)) node.fail("h_over_dp", fmt::format("expected a ratio h/dp in [0.8, 3], got {:g}", r));
  return r;
}

struct PlacedBody {
  std::string name;
  ShapePtr region;
  Real dp;
  const Vec2Array* pos;
};

FluidBody read_fluid(const SceneNode& node, const DomainBox& box, double& budget, ShapePtr& region,
                     InitialVelocity& velocity) {
  const std::string name = node.has("name") ? node.text("name") : "fluid";
  const Real dp = node.positive("dp");
  FluidBody fluid(name, dp, read_h_over_dp(node, 1.3));
  region = read_region(node, "region");
  const FillSpec fill = read_fill(node, "fill");

  FluidMaterial& m = fluid.material;
  m.eos.rho0 = node.positive("density");
  m.eos.c0 = node.positive("sound_speed");
  m.eos.kind = node.choice_or("equation_of_state", {"linear", "tait"}, "linear") == "tait" ? EquationOfStateKind::Tait
                                                                                         : EquationOfStateKind::Linear;
  m.viscosity = node.non_negative_or("viscosity", 0.0);
  m.eos.background = node.number_or("background_pressure", 0.0);

  // Without viscosity nothing else damps the particle-scale motion: the momentum dissipation is on
  // unless the scene says otherwise (reports/pressure.md, still water tank).
  fluid.riemann.momentum = m.viscosity == 0.0;
  // delta-SPH replaces the Riemann pressure-difference term of the continuity equation.
  fluid.options.delta_sph = node.non_negative_or("delta_sph", 0.0);
  if (fluid.options.delta_sph > 1.0)
    node.fail("delta_sph", fmt::format("expected a coefficient in [0, 1] (0.1 is the usual value), got {:g}", fluid.options.delta_sph));
  fluid.riemann.continuity = fluid.options.delta_sph == 0.0;
  if (const auto r = node.optional_child("riemann")) {
    fluid.riemann.continuity = r->flag_or("continuity", fluid.riemann.continuity);
    if (fluid.riemann.continuity && fluid.options.delta_sph > 0.0)
      r->fail("continuity", "the Riemann term in the continuity equation and delta_sph are two density diffusions; "
                            "expected one (set riemann.continuity to false or delta_sph to 0)");
    fluid.riemann.momentum = r->flag_or("momentum", fluid.riemann.momentum);
    fluid.riemann.damp_separating = r->choice_or("limiter", {"approaching", "separating"}, "approaching") == "separating";
    fluid.riemann.limiter_eta = r->positive_or("eta", 3.0);
    r->finish();
  }
  fluid.riemann.configure(m.eos.rho0, m.eos.c0);

  FluidOptions& o = fluid.options;
  const std::string density = node.choice_or("density_reinitialisation", {"automatic", "internal", "free_surface", "none"}, "automatic");
  o.density = density == "internal"     ? DensityReinitialisation::Internal
              : density == "free_surface" ? DensityReinitialisation::FreeSurface
              : density == "none"         ? DensityReinitialisation::None
                                          : DensityReinitialisation::Automatic;
  const std::string reference = node.choice_or("pressure_reference", {"automatic", "mean", "zero"}, "automatic");
  o.pressure_reference = reference == "mean"   ? PressureReference::Mean
                         : reference == "zero" ? PressureReference::Zero
                                               : PressureReference::Automatic;
  o.transport_velocity_alpha = node.non_negative_or("transport_velocity_alpha", 0.0);
  o.relaxation_steps = node.count_or("relaxation_steps", 0, 100000);
  o.relaxation_perturbation = node.non_negative_or("relaxation_perturbation", 0.0);
  if (o.relaxation_perturbation > 0.5)
    node.fail("relaxation_perturbation", fmt::format("expected a fraction of dp in [0, 0.5], got {:g}", o.relaxation_perturbation));
  o.reference_velocity = node.positive_or("reference_velocity", 1.0);
  o.viscous_lattice_correction = node.flag_or("viscous_lattice_correction", o.viscous_lattice_correction);
  o.pressure_lattice_correction = node.flag_or("pressure_lattice_correction", o.pressure_lattice_correction);
  o.advection_cfl = node.positive_or("advection_cfl", o.advection_cfl);
  o.acoustic_cfl = node.positive_or("acoustic_cfl", o.acoustic_cfl);
  velocity = read_initial_velocity(node);
  node.finish();

  const GeneratedParticles g = generate_body(node, name, *region, dp, fill, box, budget);
  FluidParticles& f = fluid.particles;
  f.resize(g.pos.size());
  for (std::size_t i = 0; i < g.pos.size(); ++i) {
    f.pos[i] = g.pos[i];
    f.vol[i] = g.vol[i];
    f.rho[i] = m.rho0();
    f.mass[i] = m.rho0() * g.vol[i];
    f.vel[i] = initial_velocity_at(velocity, g.pos[i]);
  }
  return fluid;
}

WallBody read_wall(const SceneNode& node, const DomainBox& box, double& budget, ShapePtr& region) {
  const std::string name = node.text("name");
  const Real dp = node.positive("dp");
  WallBody wall(name, dp, read_h_over_dp(node, 1.3));
  region = read_region(node, "region");
  const FillSpec fill = read_fill(node, "fill");
  node.finish();
  const GeneratedParticles g = generate_body(node, name, *region, dp, fill, box, budget);
  wall.particles.resize(g.pos.size());
  wall.particles.pos = g.pos;
  wall.particles.vol = g.vol;
  return wall;
}

SolidBody read_solid(const SceneNode& node, const DomainBox& box, double& budget, ShapePtr& region) {
  const std::string name = node.text("name");
  const Real dp = node.positive("dp");
  const Real h_over_dp = read_h_over_dp(node, 1.3);
  region = read_region(node, "region");
  const FillSpec fill = read_fill(node, "fill");
  const SceneNode mat = node.child("material");
  const std::string model_name = mat.choice("model", {"saint_venant_kirchhoff", "linear_elastic", "neo_hookean"});
  const Real rho = mat.positive("density");
  const Real E = mat.positive("youngs_modulus");
  const Real nu = mat.in_range("poisson_ratio", -1.0, 0.5);
  mat.finish();
  SolidBody solid(name, dp, h_over_dp, ElasticMaterial(solid_model_from_name(model_name), rho, E, nu));
  solid.options.cfl = node.positive_or("cfl", solid.options.cfl);
  solid.options.damping_coefficient = node.non_negative_or("damping", solid.options.damping_coefficient);
  solid.options.gradient_correction =
      gradient_correction_from_name(node.choice_or("gradient_correction", {"first_order", "second_order"}, "second_order"));
  ShapePtr clamp, rigid;
  if (node.has("clamp")) clamp = read_region(node, "clamp");
  if (node.has("rigid")) rigid = read_region(node, "rigid");
  struct TetherSpec { Tether tether; ShapePtr attach; std::string key; };
  std::vector<TetherSpec> tether_specs;
  for (const SceneNode& t : node.children("tethers")) {
    TetherSpec spec;
    spec.tether.anchor = t.vec2("anchor");
    spec.tether.rest_length = t.non_negative_or("rest_length", 0.0);
    spec.tether.stiffness = t.positive("stiffness");
    spec.tether.damping = t.non_negative_or("damping", 0.0);
    spec.attach = read_region(t, "attach");
    spec.key = t.path_of("attach");
    t.finish();
    tether_specs.push_back(std::move(spec));
  }
  const InitialVelocity velocity = read_initial_velocity(node);
  node.finish();

  const GeneratedParticles g = generate_body(node, name, *region, dp, fill, box, budget);
  SolidParticles& s = solid.particles;
  s.resize(g.pos.size());
  for (std::size_t a = 0; a < g.pos.size(); ++a) {
    s.pos0[a] = s.pos[a] = s.pos_acoustic_start[a] = g.pos[a];
    s.vol0[a] = g.vol[a];
    s.mass[a] = rho * g.vol[a];
    s.rho[a] = rho;
    s.constrained[a] = clamp && clamp->contains(g.pos[a]) ? 1 : 0;
    if (!s.constrained[a]) s.vel[a] = initial_velocity_at(velocity, g.pos[a]);
  }
  if (rigid) {
    RigidRegion rigid_part;
    for (std::size_t a = 0; a < g.pos.size(); ++a)
      if (rigid->contains(g.pos[a]) && !s.constrained[a]) rigid_part.particles.push_back(static_cast<Index>(a));
    if (rigid_part.particles.size() < 2) node.fail("rigid", "the rigid region holds fewer than two free particles of the body");
    solid.rigid = std::move(rigid_part);
  }
  for (TetherSpec& spec : tether_specs) {
    for (std::size_t a = 0; a < g.pos.size(); ++a)
      if (spec.attach->contains(g.pos[a])) spec.tether.particles.push_back(static_cast<Index>(a));
    if (spec.tether.particles.empty()) throw InputError(node.context().file, spec.key, "the tether attaches to no particle of the body");
    solid.tethers.push_back(std::move(spec.tether));
  }
  return solid;
}

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

// A contact of two solids, or of a solid and a wall (the wall becomes the second body), by name.
SolidContact read_solid_contact(const SceneNode& node, const Simulation& sim) {
  const Json list = node.has("bodies") ? node.raw().at("bodies") : Json();
  if (!list.is_array() || list.size() != 2 || !list[0].is_string() || !list[1].is_string())
    node.fail("bodies", "expected the names of two bodies, two solids or a solid and a wall, e.g. [\"leaflet_top\", "
                        "\"leaflet_bottom\"]");
  std::optional<std::size_t> solid[2], wall[2];
  for (int k = 0; k < 2; ++k) {
    const std::string name = list[k].get<std::string>();
    solid[k] = sim.solid_index(name);
    for (std::size_t w = 0; w < sim.walls().size() && !solid[k]; ++w)
      if (sim.walls()[w].name == name) wall[k] = w;
    if (!solid[k] && !wall[k]) node.fail("bodies", "'" + name + "' is neither a solid body nor a wall of this scene");
  }
  if (wall[0] && wall[1]) node.fail("bodies", "two walls never meet: a contact needs at least one solid body");
  SolidContact contact;
  contact.second_is_wall = wall[0] || wall[1];
  contact.first = solid[0] ? *solid[0] : *solid[1];
  contact.second = wall[0] ? *wall[0] : wall[1] ? *wall[1] : *solid[1];
  if (!contact.second_is_wall && contact.first == contact.second)
    node.fail("bodies", "a contact needs two different bodies (self-contact is not modelled)");
  for (const SolidContact& other : sim.solid_contacts)
    if (other.second_is_wall == contact.second_is_wall &&
        (contact.second_is_wall ? std::pair(other.first, other.second) == std::pair(contact.first, contact.second)
                                : std::minmax(other.first, other.second) == std::minmax(contact.first, contact.second)))
      node.fail("bodies", "this pair of bodies already has a contact");
  contact.stiffness = node.positive_or("stiffness", 0.0);
  node.finish();
  return contact;
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
  double budget = limits.max_particles;
  std::vector<PlacedBody> placed;
  std::vector<ShapePtr> regions;

  InitialVelocity fluid_velocity;
  if (const auto node = root.optional_child("fluid")) {
    ShapePtr region;
    sim->set_fluid(read_fluid(*node, box, budget, region, fluid_velocity));
    regions.push_back(region);
  }
  const std::vector<SceneNode> wall_nodes = root.children("walls");
  for (const SceneNode& node : wall_nodes) {
    ShapePtr region;
    sim->add_wall(read_wall(node, box, budget, region));
    regions.push_back(region);
  }
  const std::vector<SceneNode> solid_nodes = root.children("solids");
  for (const SceneNode& node : solid_nodes) {
    ShapePtr region;
    SolidBody& solid = sim->add_solid(read_solid(node, box, budget, region));
    regions.push_back(region);
    if (sim->has_fluid() && sim->fluid().h() < solid.h() * (1.0 - 1e-12))
      node.fail("dp", fmt::format("the method needs h_F >= h_S (paper section 3.1): fluid h = {:g} but solid '{}' has "
                                  "h = {:g}; refine the solid or coarsen the fluid",
                                  sim->fluid().h(), solid.name, solid.h()));
  }
  if (!sim->has_fluid() && sim->solids().empty())
    root.fail("", "the scene has neither a fluid nor a solid body: nothing to simulate");
  for (const SceneNode& node : root.children("solid_contacts")) sim->solid_contacts.push_back(read_solid_contact(node, *sim));

  {  // A periodic axis must hold three kernel supports, or the cell list would see a particle twice.
    Real reach = 0.0;
    if (sim->has_fluid()) reach = sim->fluid().kernel.cutoff();
    for (const auto& w : sim->walls()) reach = std::max(reach, w.kernel.cutoff());
    for (const auto& s : sim->solids()) reach = std::max(reach, s.kernel.cutoff());
    for (int a = 0; a < 2; ++a)
      if (box.periodic[a] && box.length(a) < 3.0 * reach)
        root.fail("domain", fmt::format("the periodic length along {} is {:g}, but it must be at least three kernel supports "
                                        "(3 x {:g} = {:g}): lengthen the domain or refine the particles",
                                        a == 0 ? "x" : "y", box.length(a), reach, 3.0 * reach));
  }

  {  // Names must be unique: observers and reports refer to bodies by name.
    std::vector<std::string> names;
    if (sim->has_fluid()) names.push_back(sim->fluid().name);
    for (const auto& w : sim->walls()) names.push_back(w.name);
    for (const auto& s : sim->solids()) names.push_back(s.name);
    for (std::size_t i = 0; i < names.size(); ++i)
      for (std::size_t j = i + 1; j < names.size(); ++j)
        if (names[i] == names[j]) root.fail("", "two bodies are named '" + names[i] + "'; body names must be unique");
  }
  std::size_t r = 0;
  if (sim->has_fluid()) placed.push_back({sim->fluid().name, regions[r++], sim->fluid().dp, &sim->fluid().particles.pos});
  for (const auto& w : sim->walls()) placed.push_back({w.name, regions[r++], w.dp, &w.particles.pos});
  for (const auto& s : sim->solids()) placed.push_back({s.name, regions[r++], s.dp, &s.particles.pos0});
  check_overlaps(placed, file);
  check_periodic_seams(placed, box, file);

  if (const auto node = root.optional_child("body_force")) {
    sim->body_force.constant = node->vec2_or("constant", Vec2::Zero());
    sim->body_force.amplitude = node->vec2_or("amplitude", Vec2::Zero());
    sim->body_force.angular_frequency = node->non_negative_or("angular_frequency", 0.0);
    sim->body_force.phase = node->number_or("phase", 0.0);
    sim->body_force_on_solids = node->flag_or("on_solids", true);
    node->finish();
  }
  if (const auto node = root.optional_child("inflow")) {
    if (!sim->has_fluid()) node->fail("", "an inflow needs a fluid body");
    sim->inflow = read_inflow(*node);
  }
  sim->open_boundaries = read_open_boundaries(root, *sim);

  std::string schedule_name = "multi_step_position_verlet";
  if (const auto node = root.optional_child("schedule")) {
    schedule_name = node->choice_or(
        "type", {"multi_step_position_verlet", "single_step_position_verlet", "multi_step_velocity_verlet"}, schedule_name);
    const std::string kinematics = node->choice_or(
        "solid_kinematics", {"averaged", "averaged_second_difference", "instantaneous"}, "averaged");
    sim->solid_kinematics = kinematics == "instantaneous"                ? SolidKinematics::Instantaneous
                            : kinematics == "averaged_second_difference" ? SolidKinematics::AveragedSecondDifference
                                                                         : SolidKinematics::Averaged;
    node->finish();
  }
  if (schedule_name == "multi_step_velocity_verlet" && !sim->solid_contacts.empty())
    root.fail("solid_contacts", "solid contacts are integrated by the position-based Verlet schedules only; "
                                "choose multi_step_position_verlet or single_step_position_verlet");
  scene.schedule = make_schedule(schedule_name);

  if (const auto node = root.optional_child("limits")) {
    sim->limits.speed_factor = node->positive_or("speed_factor", sim->limits.speed_factor);
    node->finish();
  }

  scene.run.end_time = root.positive("end_time");
  if (const auto node = root.optional_child("output")) {
    scene.run.observer_interval = node->non_negative_or("observer_interval", 0.0);
    scene.run.snapshot_interval = node->non_negative_or("snapshot_interval", 0.0);
    node->finish();
  }

  for (const SceneNode& node : root.children("observers")) {
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
    scene.observers.push_back(std::move(spec));
  }
  root.finish();

  sim->initialise();
  if (sim->has_fluid() && (sim->fluid().options.relaxation_steps > 0 || sim->fluid().options.relaxation_perturbation > 0.0)) {
    // the perturbation and the relaxation moved the particles
    FluidParticles& f = sim->fluid().particles;
    for (std::size_t i = 0; i < f.size(); ++i) f.vel[i] = initial_velocity_at(fluid_velocity, f.pos[i]);
  }
  for (const ObserverSpec& spec : scene.observers) {
    try {
      PointObserver probe(spec, *sim);
    } catch (const std::invalid_argument& e) {
      throw InputError(file, "observers", e.what());
    }
  }
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
