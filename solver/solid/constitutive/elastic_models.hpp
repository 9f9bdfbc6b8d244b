// The elastic models a scene can name ("material": {"model": ...}), in one table. Each is a struct in
// a file of its own with its names (the first is the canonical one), its own scene parameters (a
// list of ModelParameter, and from(values) where the list is not empty), its second Piola-Kirchhoff
// stress, strain energy density and out-of-plane stress S_zz, all from the moduli of
// elastic_moduli.hpp. Adding a model is its file and one entry in ElasticModel below; a model that
// lacks a part does not compile.
#pragma once

#include "solid/constitutive/mooney_rivlin.hpp"
#include "solid/constitutive/neo_hookean.hpp"
#include "solid/constitutive/saint_venant_kirchhoff.hpp"

#include <functional>
#include <string>
#include <variant>
#include <vector>

namespace mrsph {

using ElasticModel = std::variant<SaintVenantKirchhoff, NeoHookean, MooneyRivlin>;

// The model a scene names, its parameters given by read_parameter (the scene reader); throws
// std::invalid_argument listing every name.
ElasticModel make_elastic_model(const std::string& name, const std::function<Real(const ModelParameter&)>& read_parameter);
// The same with every parameter at its fallback.
ElasticModel elastic_model_from_name(const std::string& name);
std::vector<std::string> elastic_model_accepted_names();  // with the aliases
std::string elastic_model_name(const ElasticModel& model);
std::vector<std::string> elastic_model_names();  // canonical names, in the table's order

}  // namespace mrsph
