// A run's actuators (`run --actuators DEFORMATION+LATCH --size 1cm`): the combination's designs
// read and derived at the module's size into the plain model the simulator schedules and counts
// by (sim/actuation.h, docs/actuators.md "In the simulator").
#pragma once

#include <filesystem>
#include <string>

#include "sim/actuation.h"

namespace datomsim::frontend {

struct ActuatorChoice {
  std::string combination;          // "sma-spring+electrostatic"
  double radius = 0.01;             // m
  double thickness = 0.001;         // m
  std::filesystem::path directory;  // the folder of design files
};

// Throws a UsageError naming the value for an unknown design, anything but one deformation and
// one latch design, a bad design file, a size that makes no Datom, or a duration beyond the
// longest a run takes (docs/limits.md).
sim::ActuatorModel actuatorModel(const ActuatorChoice& choice);

}  // namespace datomsim::frontend
