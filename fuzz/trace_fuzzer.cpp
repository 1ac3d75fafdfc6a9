// What `view` reads besides scenes: traces (JSON Lines) and distance maps (reach's JSON). Either
// is accepted or refused with a message naming the line; nothing else may happen.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "export/viewer_page.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto trace = datomsim::exporting::checkTrace(text, "fuzz.jsonl");
  if (!trace.ok() && trace.error().empty()) std::abort();
  const auto overlay = datomsim::exporting::checkOverlay(text, "fuzz.json");
  if (!overlay.ok() && overlay.error().empty()) std::abort();
  (void)datomsim::exporting::looksLikeTrace(text);
  return 0;
}
