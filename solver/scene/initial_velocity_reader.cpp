#include "scene/initial_velocity_reader.hpp"

#include <string>
#include <utility>

namespace mrsph {

std::function<Vec2(const Vec2&, Real)> read_velocity_expressions(const SceneNode& node, bool of_time) {
  const std::string u = node.text("u"), v = node.text("v");
  ParameterTable table = node.context().parameters;
  for (const char* reserved : {"x", "y", "t"})
    if ((of_time || reserved[0] != 't') && table.count(reserved))
      node.fail("u", std::string("the parameter '") + reserved + "' hides the variable of the same name");
  const auto evaluate = [table, of_time](const std::string& text, const Vec2& p, Real t) {
    ParameterTable at = table;
    at["x"] = p.x();
    at["y"] = p.y();
    if (of_time) at["t"] = t;
    return evaluate_expression(text, at);
  };
  for (const auto& [key, text] : {std::pair<const char*, std::string>{"u", u}, {"v", v}}) {
    try {
      evaluate(text, Vec2::Zero(), 0.0);
    } catch (const ExpressionError& e) {
      node.fail(key, e.what());
    }
  }
  return [evaluate, u, v](const Vec2& p, Real t) { return Vec2(evaluate(u, p, t), evaluate(v, p, t)); };
}

InitialVelocity read_initial_velocity(const SceneNode& parent) {
  const auto node = parent.optional_child("initial_velocity");
  if (!node) return UniformVelocity{};
  const std::string type = node->choice("type", {"uniform", "womersley", "cantilever_mode", "expression"});
  InitialVelocity field;
  if (type == "uniform") {
    field = UniformVelocity{node->vec2("value")};
  } else if (type == "womersley") {
    WomersleyVelocity w;
    w.profile.channel_bottom = node->number_or("bottom", 0.0);
    w.profile.channel_height = node->positive("height");
    w.profile.pressure_gradient_amplitude = node->number("pressure_gradient_amplitude");
    w.profile.angular_frequency = node->positive("angular_frequency");
    w.profile.density = node->positive("density");
    w.profile.kinematic_viscosity = node->positive("kinematic_viscosity");
    w.time = node->number_or("time", 0.0);
    field = w;
  } else if (type == "expression") {
    field = VelocityField{[velocity = read_velocity_expressions(*node, false)](const Vec2& p) { return velocity(p, 0.0); }};
  } else {
    CantileverModeVelocity c;
    c.clamp_x = node->number("clamp_x");
    c.length = node->positive("length");
    c.amplitude = node->number("amplitude");
    c.kL = node->positive_or("kL", 1.875);
    field = c;
  }
  node->finish();
  return field;
}

}  // namespace mrsph
