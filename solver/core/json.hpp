// The JSON type of scene files, summaries and reports: keys keep the order they were written in.
#pragma once

#include <nlohmann/json.hpp>

namespace mrsph {

using Json = nlohmann::ordered_json;

}  // namespace mrsph
