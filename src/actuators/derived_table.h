// What a design costs at a module's size, as named rows (quantity, value, unit), and the tables of
// docs/actuators.md written from them, so that the page's figures are the code's (a test compares
// them).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "actuators/design.h"
#include "actuators/module_demand.h"
#include "datom/dimensions.h"

namespace datomsim::actuators {

struct Quantity {
  std::string name;
  double value = 0;
  std::string unit;
};

// The module's own rows: r, t, c, mass, weight, stroke, the forces asked.
std::vector<Quantity> moduleQuantities(const datom::Dimensions& size, const ModuleBody& body = {});

// A design's rows at that size (deformation: one piston motion; latch: one latch).
std::vector<Quantity> derivedQuantities(const Design& design, const datom::Dimensions& size,
                                        const ModuleBody& body = {});

// Markdown tables, one for the module and one per design, a column per radius (metres), with
// t = thicknessRatio x r. Numbers have four significant digits.
std::string derivedTablesMarkdown(std::span<const Design> designs, std::span<const double> radii,
                                  double thicknessRatio, const ModuleBody& body = {});

// Markdown tables of the designs' figures (value, unit, source; assumptions marked), in the
// order of the model's figureSpecs.
std::string designFiguresMarkdown(std::span<const Design> designs);

}  // namespace datomsim::actuators
