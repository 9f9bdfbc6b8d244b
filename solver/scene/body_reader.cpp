#include "scene/body_reader.hpp"

#include "boundary/initial_velocity.hpp"
#include "scene/initial_velocity_reader.hpp"
#include "scene/region_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace mrsph {

namespace {

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

constexpr Real kSmallestHOverDp = 0.8, kLargestHOverDp = 3.0;

// A body's particle spacing: positive and no larger than the domain (a larger one could not place two
// particles, and one near the largest double overflows the kernel's support 2 h to infinity).
Real read_spacing(const SceneNode& node, const DomainBox& box) {
  const Real dp = node.positive("dp");
  const Real extent = (box.upper - box.lower).maxCoeff();
  const Real largest_support = 2.0 * kLargestHOverDp * dp;
  if (!(dp <= extent && std::isfinite(largest_support)))
    node.fail("dp", fmt::format("expected a spacing no larger than the domain's extent {:g} (and a finite kernel support), got {:g}",
                                extent, dp));
  return dp;
}

Real read_h_over_dp(const SceneNode& node, Real fallback) {
  if (!node.has("h_over_dp")) return fallback;
  const Real r = node.number("h_over_dp");
  if (!(r >= kSmallestHOverDp && r <= kLargestHOverDp))
    node.fail("h_over_dp", fmt::format("expected a ratio h/dp in [{:g}, {:g}], got {:g}", kSmallestHOverDp, kLargestHOverDp, r));
  return r;
}

// The fluid's numerical options (FluidOptions), beyond the diffusion read with the material.
void read_fluid_options(const SceneNode& node, FluidOptions& o) {
  const std::string density = node.choice_or("density_reinitialisation", {"automatic", "internal", "free_surface", "none"}, "automatic");
  o.density = density == "internal"     ? DensityReinitialisation::Internal
              : density == "free_surface" ? DensityReinitialisation::FreeSurface
              : density == "none"         ? DensityReinitialisation::None
                                          : DensityReinitialisation::Automatic;
  const std::string reference = node.choice_or("pressure_reference", {"automatic", "mean", "linear", "zero"}, "automatic");
  o.pressure_reference = reference == "mean"     ? PressureReference::Mean
                         : reference == "linear" ? PressureReference::Linear
                         : reference == "zero"   ? PressureReference::Zero
                                                 : PressureReference::Automatic;
  o.density_relaxation = node.positive_or("density_relaxation", 1.0);
  if (o.density_relaxation > 1.0)
    node.fail("density_relaxation", fmt::format("expected a fraction in (0, 1] (1: the paper's summation), got {:g}", o.density_relaxation));
  if (o.density_relaxation != 1.0 && o.density == DensityReinitialisation::None)
    node.fail("density_relaxation", "a fraction of the summation needs one (density_reinitialisation is none)");
  o.transport_velocity_alpha = node.non_negative_or("transport_velocity_alpha", 0.0);
  o.relaxation_steps = node.count_or("relaxation_steps", 0, 100000);
  o.relaxation_perturbation = node.non_negative_or("relaxation_perturbation", 0.0);
  if (o.relaxation_perturbation > 0.5)
    node.fail("relaxation_perturbation", fmt::format("expected a fraction of dp in [0, 0.5], got {:g}", o.relaxation_perturbation));
  o.reference_velocity = node.positive_or("reference_velocity", 1.0);
  o.viscous_lattice_correction = node.flag_or("viscous_lattice_correction", o.viscous_lattice_correction);
  o.pressure_lattice_correction = node.flag_or("pressure_lattice_correction", o.pressure_lattice_correction);
  o.refresh_pair_geometry = node.flag_or("refresh_pair_geometry", o.refresh_pair_geometry);
  o.refresh_divergence_geometry = node.flag_or("refresh_divergence_geometry", o.refresh_divergence_geometry);
  o.rest_state_at_walls = node.flag_or("rest_state_at_walls", o.rest_state_at_walls);
  o.measured_pressure_moment = node.flag_or("measured_pressure_moment", o.measured_pressure_moment);
  o.pressure_gradient_correction = node.flag_or("pressure_gradient_correction", o.pressure_gradient_correction);
  if (o.pressure_gradient_correction && node.has("pressure_lattice_correction") && o.pressure_lattice_correction)
    node.fail("pressure_lattice_correction", "the kernel-gradient correction includes the lattice's moment; "
                                             "expected pressure_lattice_correction false (or absent) with pressure_gradient_correction");
  const std::string wall_velocity = node.choice_or("viscous_wall_velocity", {"extrapolated", "mirrored", "quadratic"}, "extrapolated");
  o.viscous_wall_velocity = wall_velocity == "mirrored"    ? ViscousWallVelocity::Mirrored
                            : wall_velocity == "quadratic" ? ViscousWallVelocity::Quadratic
                                                           : ViscousWallVelocity::Linear;
  if (o.measured_pressure_moment && node.has("pressure_lattice_correction") && !o.pressure_lattice_correction)
    node.fail("measured_pressure_moment", "it is the moment the pressure lattice correction divides by; "
                                          "expected pressure_lattice_correction true (or left to the flow) with it");
  const std::string wall_continuity = node.choice_or("wall_continuity", {"automatic", "summation", "mirrored"}, "automatic");
  o.mirrored_wall_continuity = wall_continuity == "mirrored";
  o.left_to_flow = {!node.has("density_relaxation"), !node.has("pressure_lattice_correction"),
                    !node.has("refresh_pair_geometry"), !node.has("rest_state_at_walls"),
                    !node.has("measured_pressure_moment"),
                    wall_continuity == "automatic"};
  o.advection_cfl = node.positive_or("advection_cfl", o.advection_cfl);
  o.max_advection_step = node.positive_or("max_advection_step", o.max_advection_step);
  o.acoustic_cfl = node.positive_or("acoustic_cfl", o.acoustic_cfl);
}

ElasticMaterial read_elastic_material(const SceneNode& mat) {
  const std::string model_name = mat.choice("model", elastic_model_accepted_names());
  const Real rho = mat.positive("density");
  const Real E = mat.positive("youngs_modulus");
  const Real nu = mat.in_range("poisson_ratio", -1.0, 0.5);
  // The model's own parameters (constitutive/elastic_models.hpp), each in its closed range.
  const ElasticModel model = make_elastic_model(model_name, [&](const ModelParameter& p) {
    const std::string key(p.key);
    const Real value = mat.number_or(key, p.fallback);
    if (!(value >= p.lower && value <= p.upper))
      mat.fail(key, fmt::format("expected {} in [{:g}, {:g}], got {:g}", p.meaning, p.lower, p.upper, value));
    return value;
  });
  mat.finish();
  return ElasticMaterial(model, rho, E, nu);
}

}  // namespace

FluidBody read_fluid(const SceneNode& node, const DomainBox& box, double& budget, ShapePtr& region,
                     InitialVelocity& velocity) {
  const std::string name = node.has("name") ? node.text("name") : "fluid";
  const Real dp = read_spacing(node, box);
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
    fluid.riemann.hydrostatic_balance = r->flag_or("hydrostatic_balance", fluid.riemann.hydrostatic_balance);
    r->finish();
  }
  fluid.riemann.configure(m.eos.rho0, m.eos.c0);

  read_fluid_options(node, fluid.options);
  if (fluid.options.rest_state_at_walls && !fluid.riemann.hydrostatic_balance)
    node.fail("rest_state_at_walls", "it continues the hydrostatic balance's rest state into the walls; "
                                     "expected riemann.hydrostatic_balance true (the default) with it");
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
  const Real dp = read_spacing(node, box);
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
  const Real dp = read_spacing(node, box);
  const Real h_over_dp = read_h_over_dp(node, 1.3);
  region = read_region(node, "region");
  const FillSpec fill = read_fill(node, "fill");
  SolidBody solid(name, dp, h_over_dp, read_elastic_material(node.child("material")));
  const Real rho = solid.material.density();
  solid.options.cfl = node.positive_or("cfl", solid.options.cfl);
  solid.options.damping_coefficient = node.non_negative_or("damping", solid.options.damping_coefficient);
  solid.options.gradient_correction =
      gradient_correction_from_name(node.choice_or(
          "gradient_correction", {"first_order", "second_order", "second_order_with_corners"}, "second_order"));
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

}  // namespace mrsph
