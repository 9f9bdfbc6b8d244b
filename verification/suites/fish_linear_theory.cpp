#include "suites/fish_linear_theory.hpp"

#include "geometry/shapes.hpp"
#include "scene/expression.hpp"
#include "theory/plate_flutter.hpp"

#include <algorithm>
#include <cmath>

namespace mrsph::verification {

namespace {

// The fish as linear flutter theory sees it (theory/plate_flutter.hpp): the scene's outline (thin
// ends dropped as in the scene), material and rigid head, in a uniform stream at the parabolic
// profile's centre-line speed 1.5 U0 (across the body, y = 4 +/- 0.2, within 0.25 % of it), held by
// the cable: a lateral stiffness tension / length at the nose, the tension the run's mean drag.
theory::SlenderBody fish_as_slender_body(const LoadedScene& scene, double cable_tension) {
  const ParameterTable& p = scene.parameters;
  const Json& solid = scene.document.at("solids").at(0);
  const Json& outline = solid.at("region").at("fish");
  auto value = [&](const Json& j) { return j.is_number() ? j.get<double>() : evaluate_expression(j.get<std::string>(), p); };
  const double length = value(outline.at("length")), thickness = value(outline.at("thickness"));
  const double min_half = value(outline.at("min_half_thickness")), nose_x = value(outline.at("head_tip").at(0));
  std::vector<double> coefficients;
  for (const Json& c : outline.at("coefficients")) coefficients.push_back(value(c));
  auto half = [=](double x) { return fish_half_thickness(length - x, length, thickness, coefficients); };  // x from the nose
  theory::SlenderBody body;
  body.thickness = [=](double x) { return 2.0 * half(x); };
  body.x_begin = length;
  body.x_end = 0.0;
  for (int k = 0; k <= 20000; ++k) {
    const double x = length * k / 20000;
    if (half(x) >= min_half) { body.x_begin = std::min(body.x_begin, x); body.x_end = std::max(body.x_end, x); }
  }
  body.rigid_until = value(solid.at("rigid").at("rectangle").at("upper").at(0)) - nose_x;
  body.solid_density = value(solid.at("material").at("density"));
  body.youngs_modulus = value(solid.at("material").at("youngs_modulus"));
  body.poisson_ratio = value(solid.at("material").at("poisson_ratio"));
  body.support = theory::NoseSupport::Tethered;
  body.lateral_stiffness = cable_tension / p.at("cable_length");
  return body;
}

}  // namespace

Json fish_linear_theory(const LoadedScene& scene, double cable_tension, bool sweep) {
  theory::SlenderBody body = fish_as_slender_body(scene, cable_tension);
  theory::FlowModel flow;
  flow.stream_speed = 1.5 * scene.parameters.at("U0");
  flow.fluid_density = scene.parameters.at("rho");
  constexpr double max_frequency = 2.0, soft = 1.0, stiff = 1000.0;
  auto modes_json = [](const std::vector<theory::Complex>& modes) {
    Json out = Json::array();
    for (const auto& l : modes)
      out.push_back({{"frequency", l.imag() / (2.0 * M_PI)}, {"growth_rate", l.real()}, {"damping_ratio", -l.real() / std::abs(l)}});
    return out;
  };
  const theory::FlutterModes modes = theory::flutter_modes(body, flow, max_frequency);
  Json out = {{"model", "unsteady thin-aerofoil theory of the outline as a plane-strain beam, rigid head, uniform stream "
                        "(verification/theory/plate_flutter.hpp)"},
              {"stream_speed", flow.stream_speed},
              {"tether_lateral_stiffness", body.lateral_stiffness},
              {"wetted_modes", modes_json(modes.wetted)},
              {"in_vacuo_modes", modes_json(modes.in_vacuo)},
              {"largest_growth_rate", modes.largest_growth(max_frequency)},
              {"unconverged_roots", modes.unconverged}};
  const auto tethered = theory::critical_youngs_modulus(body, flow, max_frequency, soft, stiff);
  body.support = theory::NoseSupport::Pinned;
  const auto pinned = theory::critical_youngs_modulus(body, flow, max_frequency, soft, stiff);
  out["critical_youngs_modulus_tethered"] = tethered ? Json(*tethered) : Json(nullptr);
  out["critical_youngs_modulus_pinned"] = pinned ? Json(*pinned) : Json(nullptr);
  if (sweep) {
    Json rows = Json::array();
    for (double e : {2.0, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 15.0, 20.0, 30.0, 50.0, 100.0, 200.0, 500.0}) {
      Json row = {{"youngs_modulus", e}};
      for (const auto& [support, name] : {std::pair{theory::NoseSupport::Tethered, "tethered"}, std::pair{theory::NoseSupport::Pinned, "pinned"}}) {
        body.support = support;
        body.youngs_modulus = e;
        const theory::FlutterModes m = theory::flutter_modes(body, flow, max_frequency);
        const auto least_damped = std::max_element(m.wetted.begin(), m.wetted.end(), [](auto a, auto b) { return a.real() < b.real(); });
        row[std::string(name) + "_growth_rate"] = least_damped == m.wetted.end() ? Json(nullptr) : Json(least_damped->real());
        row[std::string(name) + "_frequency"] = least_damped == m.wetted.end() ? Json(nullptr) : Json(least_damped->imag() / (2.0 * M_PI));
      }
      rows.push_back(row);
    }
    out["sweep"] = rows;
  }
  return out;
}

}  // namespace mrsph::verification
