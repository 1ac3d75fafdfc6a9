// The JSON scene reader on any bytes: it refuses with a message or reads a scene, which then
// writes and reads back to the same modules (the writer's output is always readable). Its fast
// path and the general reader alone give the same scene or the same error.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "io/json_scene.h"
#include "io/json_scene_handler.h"
#include "same_outcome.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto scene = datomsim::io::parseJsonScene(text, "fuzz.json");
  if (!sameOutcome(scene, datomsim::io::detail::readJsonSceneGeneral(text, "fuzz.json"))) {
    std::abort();
  }
  if (!scene.ok()) {
    if (scene.error().empty()) std::abort();  // a refusal always says why
    return 0;
  }
  const auto again = datomsim::io::parseJsonScene(datomsim::io::toJson(*scene), "again.json");
  if (!again.ok() || again->world.size() != scene->world.size()) std::abort();
  return 0;
}
