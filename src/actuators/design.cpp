#include "actuators/design.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace datomsim::actuators {
namespace {

using Json = nlohmann::json;

constexpr std::array kModels = {Model::kSmaSpring, Model::kElectroRibbon, Model::kMechanicalLatch,
                                Model::kElectromagneticLatch, Model::kElectrostaticLatch};

// The figures of each model, in the order docs/actuators.md lists them.
constexpr std::array<FigureSpec, 15> kSmaSpring = {{
    {"density", "kg/m^3"},
    {"specific_heat", "J/(kg K)"},
    {"latent_heat", "J/kg"},
    {"resistivity", "ohm m"},
    {"activation_temperature", "K"},
    {"ambient_temperature", "K"},
    {"allowable_shear_stress", "Pa"},
    {"max_shear_strain", "1", true},
    {"spring_index", "1"},
    {"heating_current_density", "A/m^2"},
    {"cooling_time_reference", "s"},
    {"cooling_reference_diameter", "m"},
    {"cooling_exponent", "1"},
    {"min_wire_diameter", "m"},
    {"bias_force_ratio", "1"},
}};
constexpr std::array<FigureSpec, 11> kElectroRibbon = {{
    {"relative_permittivity", "1"},
    {"dielectric_thickness", "m"},
    {"dielectric_strength", "V/m"},
    {"voltage", "V"},
    {"electrode_thickness", "m"},
    {"electrode_density", "kg/m^3"},
    {"width_fraction", "1", true},
    {"contraction", "1", true},
    {"specific_power", "W/kg"},
    {"ribbons_per_piston", "1"},
    {"drive_current", "A"},
}};
constexpr std::array<FigureSpec, 9> kMechanicalLatch = {{
    {"allowable_stress", "Pa"},
    {"safety_factor", "1"},
    {"hook_fraction", "1", true},
    {"travel_fraction", "1", true},
    {"drive_speed", "m/s"},
    {"dead_time", "s"},
    {"drive_efficiency", "1", true},
    {"preload_fraction", "1", true},
    {"minimum_feature", "m"},
}};
constexpr std::array<FigureSpec, 6> kElectromagneticLatch = {{
    {"flux_density", "T"},
    {"air_gap", "m"},
    {"coil_resistivity", "ohm m"},
    {"fill_factor", "1", true},
    {"window_fraction", "1", true},
    {"pole_fraction", "1", true},
}};
constexpr std::array<FigureSpec, 8> kElectrostaticLatch = {{
    {"relative_permittivity", "1"},
    {"dielectric_thickness", "m"},
    {"dielectric_strength", "V/m"},
    {"voltage", "V"},
    {"electrode_fraction", "1", true},
    {"friction_coefficient", "1"},
    {"volume_resistivity", "ohm m"},
    {"drive_current", "A"},
}};

constexpr std::string_view kFormat = "datomsim-actuator";
constexpr int kVersion = 1;

// A value as the file wrote it, for the messages.
std::string shown(const Json& value) {
  return value.dump();
}

std::string knownModels() {
  std::string names;
  for (Model model : kModels) {
    if (!names.empty()) names += ", ";
    names += modelName(model);
  }
  return names;
}

Result<Model> modelNamed(const std::string& name, const std::string& fileName) {
  for (Model model : kModels) {
    if (modelName(model) == name) return model;
  }
  return Error{fmt::format("{}: \"model\" is \"{}\", not a model of actuator (known: {})", fileName,
                           name, knownModels())};
}

const FigureSpec* specOf(Model model, std::string_view key) {
  for (const FigureSpec& spec : figureSpecs(model)) {
    if (spec.key == key) return &spec;
  }
  return nullptr;
}

// One figure: {"value": number, "unit": text, "source": text, "assumption": bool (optional)}.
Result<Figure> readFigure(const Json& entry, const FigureSpec& spec, const std::string& fileName) {
  const std::string where = fmt::format("{}: figures.{}", fileName, spec.key);
  if (!entry.is_object()) {
    return Error{fmt::format("{} is {}, not an object with a value, a unit and a source", where,
                             shown(entry))};
  }
  for (const auto& [key, value] : entry.items()) {
    if (key != "value" && key != "unit" && key != "source" && key != "assumption") {
      return Error{
          fmt::format("{}: unknown key \"{}\" (a figure holds value, unit, source and "
                      "assumption)",
                      where, key)};
    }
  }
  Figure figure;
  if (!entry.contains("value") || !entry["value"].is_number()) {
    return Error{fmt::format("{}: \"value\" must be a number, got {}", where,
                             entry.contains("value") ? shown(entry["value"]) : "nothing")};
  }
  figure.value = entry["value"].get<double>();
  if (!std::isfinite(figure.value) || figure.value <= 0) {
    return Error{
        fmt::format("{}: value {} must be finite and positive", where, shown(entry["value"]))};
  }
  if (spec.atMostOne && figure.value > 1) {
    return Error{
        fmt::format("{}: value {} is a share and must be at most 1", where, shown(entry["value"]))};
  }
  if (!entry.contains("unit") || !entry["unit"].is_string()) {
    return Error{fmt::format("{}: \"unit\" must be the text \"{}\"", where, spec.unit)};
  }
  figure.unit = entry["unit"].get<std::string>();
  if (figure.unit != spec.unit) {
    return Error{
        fmt::format("{}: unit \"{}\" is not the one accepted, \"{}\" (SI units, docs/actuators.md)",
                    where, figure.unit, spec.unit)};
  }
  if (!entry.contains("source") || !entry["source"].is_string() ||
      entry["source"].get<std::string>().empty()) {
    return Error{fmt::format("{}: \"source\" must say where the figure comes from", where)};
  }
  figure.source = entry["source"].get<std::string>();
  if (entry.contains("assumption")) {
    if (!entry["assumption"].is_boolean()) {
      return Error{fmt::format("{}: \"assumption\" must be true or false, got {}", where,
                               shown(entry["assumption"]))};
    }
    figure.assumption = entry["assumption"].get<bool>();
  }
  return figure;
}

// A voltage across a film must stay below the film's dielectric strength.
Status checkField(const Design& design, const std::string& fileName) {
  const double field = design.figure("voltage") / design.figure("dielectric_thickness");
  if (field >= design.figure("dielectric_strength")) {
    return Error{
        fmt::format("{}: voltage {:g} V across dielectric_thickness {:g} m is {:g} V/m, not below "
                    "dielectric_strength {:g} V/m",
                    fileName, design.figure("voltage"), design.figure("dielectric_thickness"),
                    field, design.figure("dielectric_strength"))};
  }
  return Ok{};
}

Status checkTopLevel(const Json& document, const std::string& fileName) {
  if (!document.is_object()) return Error{fmt::format("{}: a design is a JSON object", fileName)};
  for (const auto& [key, value] : document.items()) {
    if (key != "format" && key != "version" && key != "name" && key != "model" &&
        key != "summary" && key != "figures") {
      return Error{fmt::format(
          "{}: unknown key \"{}\" (a design holds format, version, name, model, summary and "
          "figures)",
          fileName, key)};
    }
  }
  if (!document.contains("format") || document["format"] != kFormat) {
    return Error{fmt::format("{}: \"format\" must be \"{}\", got {}", fileName, kFormat,
                             document.contains("format") ? shown(document["format"]) : "nothing")};
  }
  if (!document.contains("version") || document["version"] != kVersion) {
    return Error{
        fmt::format("{}: \"version\" must be {}, got {}", fileName, kVersion,
                    document.contains("version") ? shown(document["version"]) : "nothing")};
  }
  for (const char* key : {"name", "model", "summary"}) {
    if (!document.contains(key) || !document[key].is_string() ||
        document[key].get<std::string>().empty()) {
      return Error{fmt::format("{}: \"{}\" must be a text, got {}", fileName, key,
                               document.contains(key) ? shown(document[key]) : "nothing")};
    }
  }
  if (!document.contains("figures") || !document["figures"].is_object()) {
    return Error{fmt::format("{}: \"figures\" must be an object of figures", fileName)};
  }
  return Ok{};
}

}  // namespace

std::string_view modelName(Model model) {
  switch (model) {
    case Model::kSmaSpring:
      return "sma-spring";
    case Model::kElectroRibbon:
      return "electro-ribbon";
    case Model::kMechanicalLatch:
      return "mechanical-latch";
    case Model::kElectromagneticLatch:
      return "electromagnetic-latch";
    case Model::kElectrostaticLatch:
      return "electrostatic-latch";
  }
  return "";
}

ActuatorKind kindOf(Model model) {
  return model == Model::kSmaSpring || model == Model::kElectroRibbon ? ActuatorKind::kDeformation
                                                                      : ActuatorKind::kLatch;
}

std::span<const Model> allModels() {
  return kModels;
}

std::span<const FigureSpec> figureSpecs(Model model) {
  switch (model) {
    case Model::kSmaSpring:
      return kSmaSpring;
    case Model::kElectroRibbon:
      return kElectroRibbon;
    case Model::kMechanicalLatch:
      return kMechanicalLatch;
    case Model::kElectromagneticLatch:
      return kElectromagneticLatch;
    case Model::kElectrostaticLatch:
      return kElectrostaticLatch;
  }
  return {};
}

double Design::figure(std::string_view key) const {
  return figures.find(key)->second.value;
}

Result<Design> parseDesign(std::string_view text, const std::string& fileName) {
  // nlohmann takes a NUL byte for the end of its input, and would accept what precedes it.
  if (const size_t nul = text.find('\0'); nul != std::string_view::npos) {
    return Error{
        fmt::format("{}:{}: a NUL byte, which no JSON text holds", fileName,
                    1 + std::count(text.begin(), text.begin() + std::ptrdiff_t(nul), '\n'))};
  }
  Json document;
  try {
    document = Json::parse(text);
  } catch (const Json::exception& error) {
    // A syntax error, or a number no double holds (1e999): JSON has no infinity or NaN.
    return Error{fmt::format("{}: not JSON: {}", fileName, error.what())};
  }
  if (Status top = checkTopLevel(document, fileName); !top) return Error{top.error()};

  Design design;
  design.name = document["name"].get<std::string>();
  auto model = modelNamed(document["model"].get<std::string>(), fileName);
  if (!model) return Error{model.error()};
  design.model = *model;
  design.summary = document["summary"].get<std::string>();

  // Every figure present is one the model knows, in its unit; every one it needs is present.
  for (const auto& [key, entry] : document["figures"].items()) {
    const FigureSpec* spec = specOf(design.model, key);
    if (spec == nullptr) {
      return Error{fmt::format("{}: figures.{}: unknown key for the model {}", fileName, key,
                               modelName(design.model))};
    }
    auto figure = readFigure(entry, *spec, fileName);
    if (!figure) return Error{figure.error()};
    design.figures.emplace(key, std::move(*figure));
  }
  for (const FigureSpec& spec : figureSpecs(design.model)) {
    if (!design.figures.count(spec.key)) {
      return Error{fmt::format("{}: figures.{} is missing (the model {} needs it, in {})", fileName,
                               spec.key, modelName(design.model), spec.unit)};
    }
  }
  if (design.model == Model::kElectroRibbon || design.model == Model::kElectrostaticLatch) {
    if (Status field = checkField(design, fileName); !field) return Error{field.error()};
  }
  return design;
}

Result<Design> readDesign(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{fmt::format("cannot read {}: no such file or not readable", path.string())};
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return parseDesign(bytes.str(), path.string());
}

}  // namespace datomsim::actuators
