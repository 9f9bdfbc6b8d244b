#include "scene/region_reader.hpp"

namespace mrsph {

namespace {

constexpr int kMaxRegionDepth = 32;  // combinations nested deeper are refused (no scene needs them)

ShapePtr read_region_node(const SceneNode& node, int depth);

std::vector<ShapePtr> read_region_list(const SceneNode& parent, const std::string& key, int depth) {
  std::vector<ShapePtr> out;
  for (const SceneNode& item : parent.children(key)) out.push_back(read_region_node(item, depth + 1));
  if (out.empty()) parent.fail(key, "expected a non-empty array of regions");
  return out;
}

ShapePtr read_region_node(const SceneNode& node, int depth) {
  if (depth > kMaxRegionDepth) node.fail("", "regions nested deeper than " + std::to_string(kMaxRegionDepth) + " levels");
  const std::vector<std::string> keys = node.keys();
  if (keys.size() != 1)
    node.fail("", "a region is an object with exactly one of the keys \"rectangle\", \"circle\", \"polygon\", "
                  "\"fish\", \"union\", \"intersection\", \"difference\"");
  const std::string& kind = keys.front();
  ShapePtr shape;
  try {
    if (kind == "rectangle") {
      const SceneNode r = node.child(kind);
      shape = std::make_shared<Rectangle>(r.vec2("lower"), r.vec2("upper"));
      r.finish();
    } else if (kind == "circle") {
      const SceneNode c = node.child(kind);
      shape = std::make_shared<Circle>(c.vec2("center"), c.positive("radius"));
      c.finish();
    } else if (kind == "polygon") {
      const SceneNode p = node.child(kind);
      shape = std::make_shared<Polygon>(p.vec2_list("vertices"));
      p.finish();
    } else if (kind == "fish") {
      const SceneNode f = node.child(kind);
      const Vec2 head = f.vec2("head_tip");
      const Real length = f.positive("length"), thickness = f.positive("thickness");
      std::vector<Real> coefficients;
      const Json& list = f.raw().contains("coefficients") ? f.raw().at("coefficients") : Json();
      f.has("coefficients");
      if (!list.is_array() || list.empty()) f.fail("coefficients", "expected a non-empty array of numbers");
      for (const Json& c : list) {
        if (!c.is_number()) f.fail("coefficients", "expected numbers, got " + describe_json(c));
        coefficients.push_back(c.get<Real>());
      }
      shape = std::make_shared<Polygon>(fish_outline(head, length, thickness, coefficients, f.non_negative_or("min_half_thickness", 0.0)));
      f.finish();
    } else if (kind == "union") {
      shape = std::make_shared<Union>(read_region_list(node, kind, depth));
    } else if (kind == "intersection") {
      shape = std::make_shared<Intersection>(read_region_list(node, kind, depth));
    } else if (kind == "difference") {
      const SceneNode d = node.child(kind);
      shape = std::make_shared<Difference>(read_region_node(d.child("base"), depth + 1), read_region_list(d, "subtract", depth));
      d.finish();
    } else {
      node.fail(kind, "unknown region type; expected \"rectangle\", \"circle\", \"polygon\", \"union\", "
                      "\"intersection\" or \"difference\"");
    }
  } catch (const std::invalid_argument& e) {
    node.fail(kind, e.what());
  }
  node.finish();
  return shape;
}

}  // namespace

ShapePtr read_region(const SceneNode& parent, const std::string& key) { return read_region_node(parent.child(key), 0); }

FillSpec read_fill(const SceneNode& parent, const std::string& key) {
  FillSpec fill;
  const auto node = parent.optional_child(key);
  if (!node) return fill;
  const std::string pattern = node->choice_or("pattern", {"lattice", "rings"}, "lattice");
  fill.pattern = pattern == "rings" ? FillPattern::Rings : FillPattern::Lattice;
  if (node->has("origin")) fill.lattice_origin = node->vec2("origin");
  fill.lattice_angle = node->number_or("angle_degrees", 0.0) * kPi / 180.0;
  if (fill.pattern == FillPattern::Rings) {
    fill.ring_center = node->vec2("center");
    fill.ring_radius = node->positive("radius");
  }
  fill.clearance = node->non_negative_or("clearance", fill.clearance);
  node->finish();
  return fill;
}

}  // namespace mrsph
