#include "scene/open_boundary_reader.hpp"

#include "scene/initial_velocity_reader.hpp"
#include "scene/region_reader.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace mrsph {

namespace {

// An expression of t and the scene's parameters (a parameter named t is refused).
std::function<Real(Real)> read_time_function(const SceneNode& node, const std::string& key) {
  if (node.context().parameters.count("t")) node.fail(key, "the parameter 't' hides the variable of the same name");
  const std::string text = node.text(key);
  const auto evaluate = [table = node.context().parameters, text](Real t) {
    ParameterTable at = table;
    at["t"] = t;
    return evaluate_expression(text, at);
  };
  try {
    if (!std::isfinite(evaluate(0.0))) node.fail(key, "is not finite at t = 0");
  } catch (const ExpressionError& e) {
    node.fail(key, e.what());
  }
  return evaluate;
}

int read_axis(const SceneNode& node) { return node.choice("axis", {"x", "y"}) == "x" ? 0 : 1; }

// The refusals of issue 18: a buffer on a periodic axis or beyond the box, crossing a body, or
// without fluid in it or reaching its plane.
void check_open_boundary(const SceneNode& node, const OpenBoundary& b, const Simulation& sim) {
  const char axis_name = b.axis == 0 ? 'x' : 'y';
  const DomainBox& box = sim.box();
  if (box.periodic[b.axis])
    node.fail("axis", fmt::format("the domain is periodic along {}; an open boundary needs a non-periodic axis", axis_name));
  const FluidBody& fluid = sim.fluid();
  if (b.width < fluid.kernel.cutoff() * (1.0 - 1e-12))
    node.fail("width", fmt::format("{:g} is less than one kernel support of the fluid (2h = {:g}): the particles near the "
                                   "plane would see an empty support", b.width, fluid.kernel.cutoff()));
  const Real far_end = b.plane + b.side * b.width;
  const Real bound = b.side > 0 ? box.upper[b.axis] : box.lower[b.axis];
  if (b.side * (bound - far_end) < fluid.dp)
    node.fail("width", fmt::format("the buffer ends at {} = {:g}, but the domain ends at {:g}: the box must reach at least "
                                   "one spacing (dp = {:g}) beyond the buffer", axis_name, far_end, bound, fluid.dp));
  const int t = 1 - b.axis;
  if (b.span_lower < box.lower[t] || b.span_upper > box.upper[t])
    node.fail("span", fmt::format("[{:g}, {:g}] reaches outside the domain [{:g}, {:g}] along {}", b.span_lower, b.span_upper,
                                  box.lower[t], box.upper[t], t == 0 ? 'x' : 'y'));
  if ((b.span_upper - b.span_lower) / fluid.dp > 1e6)
    node.fail("span", fmt::format("holds {:g} fluid spacings; at most 10^6 (the buffer is extrapolated in bins of dp)",
                                  (b.span_upper - b.span_lower) / fluid.dp));
  const auto in_buffer = [&](const Vec2& p) { return b.in_buffer(p) && p[t] > b.span_lower && p[t] < b.span_upper; };
  const auto check_body = [&](const Vec2Array& pos, const std::string& body) {
    for (const Vec2& p : pos)
      if (in_buffer(p))
        node.fail("plane", fmt::format("the buffer of '{}' overlaps body '{}' (a particle at ({:g}, {:g})); a buffer must hold "
                                       "fluid only: move the plane or the body", b.name, body, p.x(), p.y()));
  };
  for (const WallBody& w : sim.walls()) check_body(w.particles.pos, w.name);
  for (const SolidBody& s : sim.solids()) check_body(s.particles.pos0, s.name);
  std::size_t in_buffer_count = 0, reaching = 0;
  for (const Vec2& p : fluid.particles.pos) {
    if (in_buffer(p)) ++in_buffer_count;
    const Real d = b.depth(p);
    if (d <= 0.0 && d > -fluid.kernel.cutoff() && p[t] > b.span_lower && p[t] < b.span_upper) ++reaching;
  }
  if (in_buffer_count == 0)
    node.fail("plane", fmt::format("the buffer of '{}' ({} from {:g} to {:g}) holds no fluid particle: the fluid region must "
                                   "fill it", b.name, axis_name, b.plane, far_end));
  if (reaching == 0)
    node.fail("plane", fmt::format("no fluid reaches the plane {} = {:g} of '{}' from the domain side", axis_name, b.plane, b.name));
  if (b.condition == OpenBoundaryCondition::Pressure) {
    const Real p0 = b.pressure(0.0);
    const Real rho = fluid.material.eos.density(p0);
    if (!(std::isfinite(rho) && rho > 0.0))
      node.fail("pressure", fmt::format("p = {:g} at t = 0 has no density in the fluid's equation of state (rho0 = {:g}, c = {:g})",
                                        p0, fluid.material.rho0(), fluid.material.sound_speed()));
  }
}

OpenBoundary read_open_boundary(const SceneNode& node, const Simulation& sim) {
  OpenBoundary b;
  b.name = node.text("name");
  b.axis = read_axis(node);
  b.side = node.choice("side", {"lower", "upper"}) == "upper" ? 1 : -1;
  b.plane = node.number("plane");
  b.width = node.positive("width");
  const int t = 1 - b.axis;
  const Vec2 span = node.vec2_or("span", Vec2(sim.box().lower[t], sim.box().upper[t]));
  b.span_lower = span[0];
  b.span_upper = span[1];
  if (!(b.span_upper > b.span_lower)) node.fail("span", "expected [lower, upper] with lower < upper");
  if (node.choice("condition", {"velocity", "pressure"}) == "velocity") {
    b.condition = OpenBoundaryCondition::Velocity;
    b.velocity = read_inflow_profile(node.child("profile"));
  } else {
    b.condition = OpenBoundaryCondition::Pressure;
    b.pressure = read_time_function(node, "pressure");
    b.reflection_time = node.non_negative_or("reflection_time", 0.0);
    b.total_pressure_inflow = node.choice_or("entering_pressure", {"static", "total"}, "static") == "total";
    b.smooth_normal_velocity = node.choice_or("normal_velocity", {"bins", "smooth"}, "bins") == "smooth";
  }
  check_open_boundary(node, b, sim);
  node.finish();
  return b;
}

}  // namespace

InflowProfile read_inflow_profile(const SceneNode& profile) {
  const std::string type = profile.choice("type", {"parabolic_channel", "womersley", "expression"});
  InflowProfile result;
  if (type == "parabolic_channel") {
    ParabolicInflowProfile p;
    p.channel_bottom = profile.number_or("bottom", 0.0);
    p.channel_height = profile.positive("height");
    p.mean_velocity = profile.number("mean_velocity");
    p.ramp_time = profile.non_negative_or("ramp_time", 0.0);
    result = p;
  } else if (type == "womersley") {
    WomersleyInflowProfile w;
    w.profile.channel_bottom = profile.number_or("bottom", 0.0);
    w.profile.channel_height = profile.positive("height");
    w.profile.pressure_gradient_amplitude = profile.number("pressure_gradient_amplitude");
    w.profile.angular_frequency = profile.positive("angular_frequency");
    w.profile.density = profile.positive("density");
    w.profile.kinematic_viscosity = profile.positive("kinematic_viscosity");
    result = w;
  } else {
    result = ExpressionInflowProfile{read_velocity_expressions(profile, true)};
  }
  profile.finish();
  return result;
}

InflowBuffer read_inflow(const SceneNode& node) {
  InflowBuffer inflow;
  inflow.region = read_region(node, "buffer");
  inflow.profile = read_inflow_profile(node.child("profile"));
  inflow.drive_channel = node.flag_or("drive_channel", inflow.drive_channel);
  node.finish();
  return inflow;
}

std::vector<OpenBoundary> read_open_boundaries(const SceneNode& root, const Simulation& sim) {
  std::vector<OpenBoundary> boundaries;
  const std::vector<SceneNode> nodes = root.children("open_boundaries");
  if (!nodes.empty() && !sim.has_fluid()) root.fail("open_boundaries", "open boundaries need a fluid body");
  if (nodes.size() > 250) root.fail("open_boundaries", "at most 250 open boundaries");
  for (const SceneNode& node : nodes) boundaries.push_back(read_open_boundary(node, sim));
  return boundaries;
}

}  // namespace mrsph
