// What a run's actuators drew (sim/energy.h), as `run --out` writes it (its "energy" section,
// docs/file-formats.md), as `run --power-csv` writes the ensemble's power over time, and as
// `run --stats` prints it.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "sim/energy.h"

namespace datomsim::frontend {

// `motions`: the run's completed motions, for the energy per motion.
nlohmann::ordered_json energyJson(const sim::EnergyReport& report, uint64_t motions);

// "time_s,power_W,energy_J": a row at every step of the ensemble's power and one at the run's
// end; energy_J is what was drawn before that time.
std::string powerCsv(const sim::EnergyReport& report);

// Lines for a person (--stats).
std::string energySummary(const sim::EnergyReport& report, uint64_t motions);

}  // namespace datomsim::frontend
