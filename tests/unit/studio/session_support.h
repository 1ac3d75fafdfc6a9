// What the studio's session tests share: the paper's arch with hole 1, a request answered as
// JSON, and the command line's run the studio's runs are held to.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "frontend/run_on_scene.h"
#include "io/scene_file.h"
#include "studio/session.h"

namespace datomsim::studio::testing {

inline io::Scene arch() {
  return *io::readScene(std::string(DATOMSIM_SOURCE_DIR) + "/scenes/paper-arch-hole1.json");
}

inline nlohmann::json ask(Session& session, const nlohmann::json& request) {
  return nlohmann::json::parse(session.handle(request.dump()));
}

// follow-gradient on the arch from 0,0,2 to 6,5,2, seed 3, as the command line runs it. (GCC 12 at
// -O3 warns of an overlap in assigning the literals, a false positive: its bug 105329.)
#pragma GCC diagnostic push
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wrestrict"
#endif
inline frontend::RunOutput commandLineRun() {
  frontend::RunArguments args;
  args.program = "follow-gradient";
  args.goal = "6,5,2";
  args.start = "0,0,2";
  args.seed = "3";
  args.wantTrace = true;
  return frontend::runOnScene(arch(), "arch", args);
}
#pragma GCC diagnostic pop

}  // namespace datomsim::studio::testing
