// What `view` reads besides scenes: traces (JSON Lines), distance maps (reach's JSON) and latch
// loads (loads' JSON, checked against a small scene's trace). Each is accepted or refused with a
// message naming the file; nothing else may happen.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "export/loads_check.h"
#include "export/viewer_page.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto trace = datomsim::exporting::checkTrace(text, "fuzz.jsonl");
  if (!trace.ok() && trace.error().empty()) std::abort();
  const auto overlay = datomsim::exporting::checkOverlay(text, "fuzz.json");
  if (!overlay.ok() && overlay.error().empty()) std::abort();
  (void)datomsim::exporting::looksLikeTrace(text);
  // Loads against the trace of two latched neighbours at rest.
  static const std::string scene =
      "{\"format\":\"datomsim-trace\",\"version\":1,\"modules\":[{\"id\":1,\"cell\":[0,0,0],"
      "\"pos\":[1,1,0.707107],\"o\":0,\"rgb\":[0,0,0],\"latches\":1},{\"id\":2,\"cell\":[1,0,0],"
      "\"pos\":[3,1,0.707107],\"o\":0,\"rgb\":[0,0,0],\"latches\":64}]}\n";
  const auto loads = datomsim::exporting::checkLoads(text, "fuzz.json", scene);
  if (!loads.ok() && loads.error().empty()) std::abort();
  return 0;
}
