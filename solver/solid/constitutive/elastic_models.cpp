#include "solid/constitutive/elastic_models.hpp"

#include <array>
#include <optional>
#include <stdexcept>
#include <utility>

namespace mrsph {

namespace {

// fn(model) for a default-constructed model of each kind, in the table's order.
template <class Fn>
void for_each_model(Fn&& fn) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (fn(std::variant_alternative_t<I, ElasticModel>{}), ...);
  }(std::make_index_sequence<std::variant_size_v<ElasticModel>>{});
}

// "a" (alias "b"), "c" or "d"
std::string expected_names() {
  std::vector<std::string> entries;
  for_each_model([&](auto model) {
    const auto& names = decltype(model)::names;
    std::string entry = "\"" + std::string(names[0]) + "\"";
    for (std::size_t k = 1; k < names.size(); ++k) entry += " (alias \"" + std::string(names[k]) + "\")";
    entries.push_back(entry);
  });
  std::string text;
  for (std::size_t k = 0; k < entries.size(); ++k)
    text += (k == 0 ? "" : k + 1 == entries.size() ? " or " : ", ") + entries[k];
  return text;
}

template <class Model>
Model build(const std::function<Real(const ModelParameter&)>& read_parameter) {
  if constexpr (Model::parameters.empty()) {
    return Model{};
  } else {
    std::array<Real, Model::parameters.size()> values{};
    for (std::size_t k = 0; k < values.size(); ++k) values[k] = read_parameter(Model::parameters[k]);
    return Model::from(values);
  }
}

}  // namespace

ElasticModel make_elastic_model(const std::string& name, const std::function<Real(const ModelParameter&)>& read_parameter) {
  std::optional<ElasticModel> found;
  for_each_model([&](auto model) {
    using Model = decltype(model);
    for (std::string_view n : Model::names)
      if (n == name && !found) found = build<Model>(read_parameter);
  });
  if (!found) throw std::invalid_argument("unknown solid model '" + name + "', expected " + expected_names());
  return *found;
}

ElasticModel elastic_model_from_name(const std::string& name) {
  return make_elastic_model(name, [](const ModelParameter& p) { return p.fallback; });
}

std::vector<std::string> elastic_model_accepted_names() {
  std::vector<std::string> names;
  for_each_model([&](auto model) {
    for (std::string_view n : decltype(model)::names) names.emplace_back(n);
  });
  return names;
}

std::string elastic_model_name(const ElasticModel& model) {
  return std::visit([](auto m) { return std::string(decltype(m)::names[0]); }, model);
}

std::vector<std::string> elastic_model_names() {
  std::vector<std::string> names;
  for_each_model([&](auto model) { names.emplace_back(decltype(model)::names[0]); });
  return names;
}

}  // namespace mrsph
