// What `geometry --json` prints and Python's datomsim.geometry returns: a Datom's dimensions
// from r and t, and with a compression fraction its joint angles (degrees).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>

namespace datomsim::frontend {

nlohmann::ordered_json geometryJson(double radius, double thickness,
                                    const std::optional<double>& fraction);

}  // namespace datomsim::frontend
