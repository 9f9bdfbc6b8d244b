#include "scene/scene_node.hpp"

#include <cmath>
#include <sstream>

namespace mrsph {

std::string describe_json(const Json& value) {
  std::string text = value.dump();
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  const char* type = value.is_number() ? "number" : value.is_string() ? "string" : value.is_boolean() ? "boolean"
                   : value.is_array() ? "array" : value.is_object() ? "object" : "null";
  return std::string(type) + " " + text;
}

SceneNode::SceneNode(const Json& node, std::shared_ptr<const SceneContext> context, std::string path)
    : node_(node), context_(std::move(context)), path_(std::move(path)), used_(std::make_shared<std::set<std::string>>()),
      asked_(std::make_shared<std::set<std::string>>()) {
  if (!node_.is_object()) throw InputError(context_->file, path_, "expected an object, got " + describe_json(node_));
}

void SceneNode::fail(const std::string& key, const std::string& problem) const {
  throw InputError(context_->file, key.empty() ? path_ : path_of(key), problem);
}

bool SceneNode::has(const std::string& key) const {
  asked_->insert(key);
  if (node_.contains(key)) { used_->insert(key); return true; }
  return false;
}

const Json& SceneNode::at(const std::string& key) const {
  asked_->insert(key);
  if (!node_.contains(key)) fail(key, "required key is missing");
  used_->insert(key);
  return node_.at(key);
}

Real SceneNode::to_number(const Json& value, const std::string& key) const {
  Real x = 0.0;
  if (value.is_number()) {
    x = value.get<Real>();
  } else if (value.is_string()) {
    try {
      x = evaluate_expression(value.get<std::string>(), context_->parameters);
    } catch (const ExpressionError& e) {
      fail(key, e.what());
    }
  } else {
    fail(key, "expected a number or an expression string, got " + describe_json(value));
  }
  if (!std::isfinite(x)) fail(key, "expected a finite number, got " + describe_json(value) + " = " + std::to_string(x));
  return x;
}

Real SceneNode::number(const std::string& key) const { return to_number(at(key), key); }
Real SceneNode::number_or(const std::string& key, Real fallback) const { return has(key) ? number(key) : fallback; }

Real SceneNode::positive(const std::string& key) const {
  const Real x = number(key);
  if (!(x > 0.0)) fail(key, "expected a positive number, got " + describe_json(node_.at(key)) + " = " + std::to_string(x));
  return x;
}
Real SceneNode::positive_or(const std::string& key, Real fallback) const { return has(key) ? positive(key) : fallback; }
Real SceneNode::non_negative_or(const std::string& key, Real fallback) const {
  if (!has(key)) return fallback;
  const Real x = number(key);
  if (x < 0.0) fail(key, "expected a number >= 0, got " + std::to_string(x));
  return x;
}
int SceneNode::count_or(const std::string& key, int fallback, int max) const {
  if (!has(key)) return fallback;
  const Real x = number(key);
  if (!(x >= 0.0 && x <= max && x == std::floor(x))) {
    std::ostringstream s;
    s << "expected a whole number from 0 to " << max << ", got " << x;
    fail(key, s.str());
  }
  return static_cast<int>(x);
}
Real SceneNode::in_range(const std::string& key, Real lo, Real hi) const {
  const Real x = number(key);
  if (!(x > lo && x < hi)) {
    std::ostringstream s;
    s << "expected a number in (" << lo << ", " << hi << "), got " << x;
    fail(key, s.str());
  }
  return x;
}

Vec2 SceneNode::to_vec2(const Json& value, const std::string& key) const {
  if (!value.is_array() || value.size() != 2) fail(key, "expected a pair [x, y], got " + describe_json(value));
  return Vec2(to_number(value[0], key + "[0]"), to_number(value[1], key + "[1]"));
}
Vec2 SceneNode::vec2(const std::string& key) const { return to_vec2(at(key), key); }
Vec2 SceneNode::vec2_or(const std::string& key, const Vec2& fallback) const { return has(key) ? vec2(key) : fallback; }

std::vector<Vec2> SceneNode::vec2_list(const std::string& key) const {
  const Json& value = at(key);
  if (!value.is_array()) fail(key, "expected an array of pairs [[x, y], ...], got " + describe_json(value));
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < value.size(); ++k) out.push_back(to_vec2(value[k], key + "[" + std::to_string(k) + "]"));
  return out;
}

std::string SceneNode::text(const std::string& key) const {
  const Json& value = at(key);
  if (!value.is_string()) fail(key, "expected a string, got " + describe_json(value));
  return value.get<std::string>();
}

std::string SceneNode::choice(const std::string& key, std::initializer_list<const char*> allowed) const {
  return choice(key, std::vector<std::string>(allowed.begin(), allowed.end()));
}
std::string SceneNode::choice(const std::string& key, const std::vector<std::string>& allowed) const {
  const std::string value = text(key);
  std::string list;
  for (const std::string& a : allowed) {
    if (value == a) return value;
    list += (list.empty() ? "\"" : ", \"") + a + "\"";
  }
  fail(key, "unknown value \"" + value + "\", expected one of " + list);
}
std::string SceneNode::choice_or(const std::string& key, std::initializer_list<const char*> allowed,
                                 const std::string& fallback) const {
  return has(key) ? choice(key, allowed) : fallback;
}

bool SceneNode::flag_or(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  const Json& value = at(key);
  if (!value.is_boolean()) fail(key, "expected true or false, got " + describe_json(value));
  return value.get<bool>();
}

std::array<bool, 2> SceneNode::flag_pair_or(const std::string& key, std::array<bool, 2> fallback) const {
  if (!has(key)) return fallback;
  const Json& value = at(key);
  if (!value.is_array() || value.size() != 2 || !value[0].is_boolean() || !value[1].is_boolean())
    fail(key, "expected a pair of booleans [x, y], got " + describe_json(value));
  return {value[0].get<bool>(), value[1].get<bool>()};
}

SceneNode SceneNode::child(const std::string& key) const {
  const Json& value = at(key);
  if (!value.is_object()) fail(key, "expected an object, got " + describe_json(value));
  return SceneNode(value, context_, path_of(key));
}
std::optional<SceneNode> SceneNode::optional_child(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  return child(key);
}

std::vector<SceneNode> SceneNode::children(const std::string& key) const {
  std::vector<SceneNode> out;
  if (!has(key)) return out;
  const Json& value = at(key);
  if (!value.is_array()) fail(key, "expected an array of objects, got " + describe_json(value));
  for (std::size_t k = 0; k < value.size(); ++k) {
    const std::string item = path_of(key) + "[" + std::to_string(k) + "]";
    if (!value[k].is_object()) throw InputError(context_->file, item, "expected an object, got " + describe_json(value[k]));
    out.emplace_back(value[k], context_, item);
  }
  return out;
}

std::vector<std::string> SceneNode::keys() const {
  std::vector<std::string> out;
  for (auto it = node_.begin(); it != node_.end(); ++it) out.push_back(it.key());
  return out;
}

void SceneNode::finish() const {
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    if (used_->count(it.key())) continue;
    std::string known;
    for (const auto& k : *asked_) known += (known.empty() ? "" : ", ") + k;
    fail(it.key(), "unknown key (misspelt, or not valid here)" +
                       (known.empty() ? std::string() : "; valid keys here: " + known));
  }
}

}  // namespace mrsph
