// The constants of the laws (CODATA 2018), SI units.
#pragma once

namespace datomsim::actuators {

// Vacuum permittivity e0, F/m.
inline constexpr double kVacuumPermittivity = 8.8541878128e-12;
// Vacuum permeability mu0, H/m.
inline constexpr double kVacuumPermeability = 1.25663706212e-6;

}  // namespace datomsim::actuators
