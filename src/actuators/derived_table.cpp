#include "actuators/derived_table.h"

#include <fmt/format.h>

#include "actuators/deformation_laws.h"
#include "actuators/latch_laws.h"

namespace datomsim::actuators {
namespace {

std::vector<Quantity> smaSpringRows(const Design& design, const datom::Dimensions& size,
                                    const ModuleDemand& demand) {
  const SmaSpringMotion m = smaSpringMotion(smaSpringFigures(design), size, demand);
  return {{"spring force", m.force, "N"},
          {"wire diameter", m.wireDiameter, "m"},
          {"coil diameter", m.coilDiameter, "m"},
          {"wire length", m.wireLength, "m"},
          {"active coils", m.activeCoils, "1"},
          {"length needed / space", m.lengthNeeded / m.space, "1"},
          {"wire mass", m.wireMass, "kg"},
          {"heating energy per motion", m.heatingEnergy, "J"},
          {"heating current", m.current, "A"},
          {"heating power", m.heatingPower, "W"},
          {"heating time", m.heatingTime, "s"},
          {"cooling time", m.coolingTime, "s"}};
}

std::vector<Quantity> electroRibbonRows(const Design& design, const datom::Dimensions& size,
                                        const ModuleDemand& demand) {
  const ElectroRibbonFigures figures = electroRibbonFigures(design);
  const ElectroRibbonMotion m = electroRibbonMotion(figures, size, demand);
  return {{"force per ribbon", m.ribbonForce, "N"},
          {"ribbon width", m.width, "m"},
          {"ribbon length", m.length, "m"},
          {"force per ribbon at the voltage", m.forceAtVoltage, "N"},
          {"force margin", m.forceAtVoltage / m.ribbonForce, "1"},
          {"voltage needed", m.voltageNeeded, "V"},
          {"voltage needed / breakdown",
           m.voltageNeeded / (figures.dielectricStrength * figures.dielectricThickness), "1"},
          {"energy per motion", m.energy, "J"},
          {"charge time", m.chargeTime, "s"},
          {"time at the specific power", m.powerTime, "s"},
          {"motion time", m.time, "s"}};
}

std::vector<Quantity> latchRows(const LatchFigures& latch, const ModuleDemand& demand) {
  return {{"holding force", latch.force, "N"},
          {"force margin", latch.force / demand.latchForce, "1"},
          {"latching time", latch.latchingTime, "s"},
          {"energy to latch", latch.latchEnergy, "J"},
          {"energy to unlatch", latch.unlatchEnergy, "J"},
          {"holding power", latch.holdingPower, "W"}};
}

std::string number(double value) {
  return fmt::format("{:.4g}", value);
}

std::string table(const std::string& title, const std::vector<std::vector<Quantity>>& columns,
                  std::span<const double> radii) {
  std::string text = fmt::format("**{}**\n\n| quantity | unit |", title);
  for (double r : radii) text += fmt::format(" r = {} m |", number(r));
  text += "\n|---|---|";
  for (size_t i = 0; i < radii.size(); ++i) text += "---|";
  text += "\n";
  for (size_t row = 0; row < columns.front().size(); ++row) {
    text += fmt::format("| {} | {} |", columns.front()[row].name, columns.front()[row].unit);
    for (const auto& column : columns) text += fmt::format(" {} |", number(column[row].value));
    text += "\n";
  }
  return text;
}

}  // namespace

std::vector<Quantity> moduleQuantities(const datom::Dimensions& size, const ModuleBody& body) {
  const ModuleDemand demand = demandOf(size, body);
  return {{"radius r", size.radius(), "m"},
          {"thickness t", size.thickness(), "m"},
          {"connector width c", size.connectorWidth(), "m"},
          {"mass", demand.mass, "kg"},
          {"weight", demand.weight, "N"},
          {"piston stroke a", demand.stroke, "m"},
          {"piston force asked", demand.pistonForce, "N"},
          {"latch force asked", demand.latchForce, "N"}};
}

std::vector<Quantity> derivedQuantities(const Design& design, const datom::Dimensions& size,
                                        const ModuleBody& body) {
  const ModuleDemand demand = demandOf(size, body);
  switch (design.model) {
    case Model::kSmaSpring:
      return smaSpringRows(design, size, demand);
    case Model::kElectroRibbon:
      return electroRibbonRows(design, size, demand);
    case Model::kMechanicalLatch: {
      const MechanicalLatchFigures figures = mechanicalLatchFigures(design);
      auto rows = latchRows(mechanicalLatch(figures, size), demand);
      rows.push_back(
          {"thickness / minimum feature", size.thickness() / figures.minimumFeature, "1"});
      return rows;
    }
    case Model::kElectromagneticLatch: {
      const ElectromagneticLatch magnet =
          electromagneticLatch(electromagneticLatchFigures(design), size);
      auto rows = latchRows(magnet.latch, demand);
      rows.push_back({"ampere-turns", magnet.ampereTurns, "A"});
      rows.push_back({"holding power / weight", magnet.latch.holdingPower / demand.weight, "W/N"});
      return rows;
    }
    case Model::kElectrostaticLatch: {
      const ElectrostaticLatchFigures figures = electrostaticLatchFigures(design);
      const ElectrostaticLatch latch = electrostaticLatch(figures, size);
      auto rows = latchRows(latch.latch, demand);
      rows.push_back({"shear force (friction)", latch.shearForce, "N"});
      rows.push_back({"voltage for the force asked",
                      electrostaticVoltageFor(figures, size, demand.latchForce), "V"});
      return rows;
    }
  }
  return {};
}

std::string derivedTablesMarkdown(std::span<const Design> designs, std::span<const double> radii,
                                  double thicknessRatio, const ModuleBody& body) {
  std::vector<datom::Dimensions> sizes;
  for (double r : radii) sizes.push_back(*datom::dimensionsFor(r, thicknessRatio * r));
  std::vector<std::vector<Quantity>> module;
  for (const auto& size : sizes) module.push_back(moduleQuantities(size, body));
  std::string text = table("the module", module, radii);
  for (const Design& design : designs) {
    std::vector<std::vector<Quantity>> columns;
    for (const auto& size : sizes) columns.push_back(derivedQuantities(design, size, body));
    text += "\n";
    text += table(design.name, columns, radii);
  }
  return text;
}

std::string designFiguresMarkdown(std::span<const Design> designs) {
  std::string text;
  for (const Design& design : designs) {
    if (!text.empty()) text += "\n";
    const bool deforms = kindOf(design.model) == ActuatorKind::kDeformation;
    text += fmt::format("**{}** ({})\n\n| figure | value | unit | source |\n|---|---|---|---|\n",
                        design.name, deforms ? "deformation" : "latch");
    for (const FigureSpec& spec : figureSpecs(design.model)) {
      const Figure& figure = design.figures.find(spec.key)->second;
      // An assumption says so first, in bold, whether or not its source text starts with it.
      constexpr std::string_view kWord = "assumption";
      std::string source = figure.source;
      if (figure.assumption) {
        if (source.starts_with(kWord)) source.erase(0, kWord.size());
        if (!source.starts_with(":")) source.insert(0, ": ");
        source.insert(0, "**assumption**");
      }
      text +=
          fmt::format("| `{}` | {:g} | {} | {} |\n", spec.key, figure.value, figure.unit, source);
    }
  }
  return text;
}

}  // namespace datomsim::actuators
