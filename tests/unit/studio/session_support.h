// What the studio's session tests share: the paper's arch with hole 1, and a request answered
// as JSON.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "io/scene_file.h"
#include "studio/session.h"

namespace datomsim::studio::testing {

inline io::Scene arch() {
  return *io::readScene(std::string(DATOMSIM_SOURCE_DIR) + "/scenes/paper-arch-hole1.json");
}

inline nlohmann::json ask(Session& session, const nlohmann::json& request) {
  return nlohmann::json::parse(session.handle(request.dump()));
}

}  // namespace datomsim::studio::testing
