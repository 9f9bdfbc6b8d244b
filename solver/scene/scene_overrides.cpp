#include "scene/scene_loader.hpp"

#include <fstream>
#include <sstream>

namespace mrsph {

namespace {

// Nesting deeper than this is refused before parsing: the JSON library parses and destroys
// recursively, and no scene needs more than a few tens of levels.
constexpr int kMaxJsonDepth = 256;

void check_nesting(const std::string& text, const std::string& file) {
  int depth = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        throw InputError(file, "", "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

}  // namespace

Json read_scene_document(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string(), "", "cannot open the scene file (does it exist and is it readable?)");
  std::stringstream buffer;
  buffer << in.rdbuf();
  check_nesting(buffer.str(), path.string());
  try {
    return Json::parse(buffer.str());
  } catch (const Json::exception& e) {  // syntax errors, and numbers out of range (1e400)
    throw InputError(path.string(), "", std::string("invalid JSON: ") + e.what());
  }
}

namespace {

struct PathStep {
  std::string key;  // empty for an index step
  std::size_t index = 0;
};

std::vector<PathStep> parse_path(const std::string& path, const std::string& file) {
  std::vector<PathStep> steps;
  std::size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos) throw InputError(file, path, "override path has '[' without ']'");
      const std::string digits = path.substr(i + 1, close - i - 1);
      if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos)
        throw InputError(file, path, "override path index '" + digits + "' is not a non-negative integer");
      steps.push_back({"", std::stoul(digits)});
      i = close + 1;
      if (i < path.size() && path[i] == '.') ++i;
      continue;
    }
    const std::size_t end = path.find_first_of(".[", i);
    const std::string key = path.substr(i, end == std::string::npos ? std::string::npos : end - i);
    if (key.empty()) throw InputError(file, path, "override path has an empty key");
    steps.push_back({key, 0});
    if (end == std::string::npos) break;
    i = path[end] == '.' ? end + 1 : end;
  }
  if (steps.empty()) throw InputError(file, path, "empty override path");
  return steps;
}

}  // namespace

void apply_override(Json& document, const std::string& assignment, const std::string& file) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(file, assignment, "an override is written path=value, e.g. fluid.dp=0.05");
  const std::string path = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  Json value;
  try {
    value = Json::parse(text);
  } catch (const Json::parse_error&) {
    value = text;  // a bare word or an expression: keep it as a string
  }
  const std::vector<PathStep> steps = parse_path(path, file);
  Json* node = &document;
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const bool last = s + 1 == steps.size();
    const PathStep& step = steps[s];
    if (last && value.is_null() && !step.key.empty()) {  // key=null removes an optional key
      if (!node->is_object() || !node->contains(step.key))
        throw InputError(file, path, "override path: no key '" + step.key + "' to remove");
      node->erase(step.key);
      return;
    }
    if (step.key.empty()) {
      if (!node->is_array() || step.index >= node->size())
        throw InputError(file, path, "override path: no element [" + std::to_string(step.index) + "] here");
      node = &(*node)[step.index];
    } else {
      if (!node->is_object()) throw InputError(file, path, "override path: '" + step.key + "' is not inside an object");
      // The last key may be new (an optional setting absent from the file); the scene reader then
      // rejects it if it is not a valid key there.
      if (!last && !node->contains(step.key))
        throw InputError(file, path, "override path: no key '" + step.key + "' in the scene");
      node = &(*node)[step.key];
    }
  }
  *node = value;
}

}  // namespace mrsph
