// An actuator design as data: a file per design (data/actuators/NAME.json, docs/actuators.md)
// holding its figures in SI units, each with the published source it comes from or the word that
// it is an assumption.
//
// A design is of one of five models: two deformation actuators that drive a piston (an SMA coil
// spring, electro-ribbons) and three latches (mechanical, electromagnetic, electrostatic). The
// model fixes which figures a file must hold and in which unit (figureSpecs); the scaling laws
// (scaling_laws.h) turn them into what one motion or one latching costs at a module's size.
#pragma once

#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <string_view>

#include "datomsim/result.h"

namespace datomsim::actuators {

enum class ActuatorKind { kDeformation, kLatch };

enum class Model {
  kSmaSpring,
  kElectroRibbon,
  kMechanicalLatch,
  kElectromagneticLatch,
  kElectrostaticLatch,
};

// The model's name as files spell it ("sma-spring", ..., "electrostatic-latch").
std::string_view modelName(Model model);
ActuatorKind kindOf(Model model);
// The five models, deformation ones first.
std::span<const Model> allModels();

// One figure a model needs: its key in the file, the one unit accepted (SI, as the docs write it)
// and whether it is a share (at most 1). Every figure is finite and positive.
struct FigureSpec {
  std::string_view key;
  std::string_view unit;
  bool atMostOne = false;
};
std::span<const FigureSpec> figureSpecs(Model model);

// One figure of a design file: its value in the spec's unit and where it comes from.
struct Figure {
  double value = 0;
  std::string unit;
  std::string source;
  bool assumption = false;
};

struct Design {
  std::string name;
  Model model = Model::kSmaSpring;
  std::string summary;
  std::map<std::string, Figure, std::less<>> figures;

  // The value of a figure the model requires (the reader has checked that it is there).
  double figure(std::string_view key) const;
};

// Reads a design from its JSON text; `fileName` names it in the errors, which say the key and the
// value refused: unknown keys, missing figures, wrong units, values that are not finite and
// positive (or above 1 for a share), a missing source.
Result<Design> parseDesign(std::string_view text, const std::string& fileName);
Result<Design> readDesign(const std::filesystem::path& path);

}  // namespace datomsim::actuators
