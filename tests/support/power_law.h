// Scaling laws in tests: the power of r between the 1 cm and the 10 cm module.
#pragma once

#include <cmath>

namespace datomsim::testing {

// The exponent k of a figure that grows as r^k, from its values at r = 1 cm and r = 10 cm.
inline double powerOfR(double at1cm, double at10cm) {
  return std::log10(at10cm / at1cm);
}

}  // namespace datomsim::testing
