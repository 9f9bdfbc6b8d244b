// Typed, path-aware access to one JSON object of a scene file. Every error names the file, the
// key as a JSON path ("solids[0].material.poisson_ratio"), the value found and what was expected.
// Numbers may be written as JSON numbers or as expression strings over the scene's parameters.
// finish() rejects keys that were never read, so a misspelt key is an error, not a silent default.
#pragma once

#include "core/errors.hpp"
#include "core/json.hpp"
#include "core/types.hpp"
#include "scene/expression.hpp"

#include <initializer_list>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace mrsph {


struct SceneContext {
  std::string file;
  ParameterTable parameters;
};

class SceneNode {
 public:
  SceneNode(const Json& node, std::shared_ptr<const SceneContext> context, std::string path);

  bool has(const std::string& key) const;
  const std::string& path() const { return path_; }
  std::string path_of(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;

  Real number(const std::string& key) const;
  Real number_or(const std::string& key, Real fallback) const;
  Real positive(const std::string& key) const;
  Real positive_or(const std::string& key, Real fallback) const;
  Real non_negative_or(const std::string& key, Real fallback) const;
  Real in_range(const std::string& key, Real lo, Real hi) const;  // lo < value < hi
  int count_or(const std::string& key, int fallback, int max) const;  // a whole number in [0, max]
  Vec2 vec2(const std::string& key) const;
  Vec2 vec2_or(const std::string& key, const Vec2& fallback) const;
  std::vector<Vec2> vec2_list(const std::string& key) const;
  std::string text(const std::string& key) const;
  std::string choice(const std::string& key, std::initializer_list<const char*> allowed) const;
  std::string choice(const std::string& key, const std::vector<std::string>& allowed) const;
  std::string choice_or(const std::string& key, std::initializer_list<const char*> allowed, const std::string& fallback) const;
  bool flag_or(const std::string& key, bool fallback) const;
  std::array<bool, 2> flag_pair_or(const std::string& key, std::array<bool, 2> fallback) const;

  SceneNode child(const std::string& key) const;
  std::optional<SceneNode> optional_child(const std::string& key) const;
  std::vector<SceneNode> children(const std::string& key) const;  // array of objects; absent: empty
  std::vector<std::string> keys() const;
  const Json& raw() const { return node_; }
  const SceneContext& context() const { return *context_; }

  void finish() const;

 private:
  const Json& at(const std::string& key) const;
  Real to_number(const Json& value, const std::string& key) const;
  Vec2 to_vec2(const Json& value, const std::string& key) const;

  const Json& node_;
  std::shared_ptr<const SceneContext> context_;
  std::string path_;
  std::shared_ptr<std::set<std::string>> used_;   // keys present and read
  std::shared_ptr<std::set<std::string>> asked_;  // every key the reader asked for: the valid keys here
};

std::string describe_json(const Json& value);  // short, for error messages

}  // namespace mrsph
