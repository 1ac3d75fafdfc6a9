#include "frontend/actuators_json.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "actuators/combination.h"
#include "actuators/derived_table.h"
#include "datom/dimensions.h"
#include "frontend/usage_error.h"

namespace datomsim::frontend {
namespace {

nlohmann::ordered_json quantitiesJson(const std::vector<actuators::Quantity>& quantities) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const actuators::Quantity& quantity : quantities) {
    out[quantity.name] = {{"value", quantity.value}, {"unit", quantity.unit}};
  }
  return out;
}

// The names the request gives: one design, or a combination's two (deformation first).
std::vector<std::string> designNames(const std::string& text) {
  if (text.find('+') == std::string::npos) return {unwrap(actuators::designName(text))};
  const actuators::Combination combination = unwrap(actuators::parseCombination(text));
  return {combination.deformation, combination.latch};
}

}  // namespace

double parseLength(std::string_view text, std::string_view option) {
  const std::string whole(text);
  // The unit's factor to metres; the longest suffix first, so that "mm" is not read as "m".
  double factor = 1.0;
  std::string number = whole;
  for (const auto& [suffix, scale] :
       {std::pair{"mm", 1e-3}, std::pair{"cm", 1e-2}, std::pair{"m", 1.0}}) {
    if (whole.size() > std::string_view(suffix).size() && whole.ends_with(suffix)) {
      number = whole.substr(0, whole.size() - std::string_view(suffix).size());
      factor = scale;
      break;
    }
  }
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(value) ||
      value <= 0) {
    throw UsageError(
        fmt::format("{} {}: expected a positive length with its unit, e.g. 1mm, 1cm, 10cm or 0.02m",
                    option, whole));
  }
  return value * factor;
}

std::vector<std::filesystem::path> actuatorDesignCandidates(
    const std::filesystem::path& executableDirectory) {
  const std::filesystem::path prefix = executableDirectory.parent_path();
  return {prefix / "share" / "datomsim" / "actuators",
          prefix.parent_path() / "share" / "datomsim" / "actuators"};
}

std::filesystem::path actuatorDesignDirectory(const std::filesystem::path& explicitDirectory,
                                              const std::filesystem::path& executableDirectory) {
  if (!explicitDirectory.empty()) return explicitDirectory;
  const auto candidates = actuatorDesignCandidates(executableDirectory);
  for (const std::filesystem::path& candidate : candidates) {
    std::error_code error;
    if (std::filesystem::is_directory(candidate, error)) return candidate;
  }
  throw UsageError(fmt::format(
      "the actuator designs are not found: no {} nor {}; pass --designs DIR (the project's "
      "data/actuators)",
      candidates[0].string(), candidates[1].string()));
}

nlohmann::ordered_json actuatorsShowJson(const ActuatorsShowRequest& request) {
  const std::vector<std::string> names = designNames(request.designs);
  const datom::Dimensions size = unwrap(datom::dimensionsFor(request.radius, request.thickness));
  nlohmann::ordered_json out;
  out["radius"] = request.radius;
  out["thickness"] = request.thickness;
  out["module"] = quantitiesJson(actuators::moduleQuantities(size));
  out["designs"] = nlohmann::ordered_json::array();
  for (const std::string& name : names) {
    const actuators::Design design = unwrap(actuators::loadDesign(request.directory, name));
    const bool deforms = actuators::kindOf(design.model) == actuators::ActuatorKind::kDeformation;
    out["designs"].push_back(
        {{"name", design.name},
         {"model", std::string(actuators::modelName(design.model))},
         {"kind", deforms ? "deformation" : "latch"},
         {"quantities", quantitiesJson(actuators::derivedQuantities(design, size))}});
  }
  return out;
}

}  // namespace datomsim::frontend
