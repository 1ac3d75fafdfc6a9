// The actuator design reader on any bytes: it refuses with a message or reads a design whose every
// figure the model needs is there, finite and positive, and which the scaling laws then derive
// at a size without failing.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "actuators/derived_table.h"
#include "actuators/design.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto design = datomsim::actuators::parseDesign(text, "fuzz.json");
  if (!design.ok()) {
    if (design.error().empty()) std::abort();  // a refusal always says why
    return 0;
  }
  for (const auto& spec : datomsim::actuators::figureSpecs(design->model)) {
    const double value = design->figure(spec.key);
    if (!std::isfinite(value) || value <= 0) std::abort();
  }
  const auto dimensions = datomsim::datom::dimensionsFor(0.01, 0.001);
  if (!dimensions.ok()) std::abort();
  const auto rows = datomsim::actuators::derivedQuantities(*design, *dimensions);
  if (rows.empty()) std::abort();
  return 0;
}
