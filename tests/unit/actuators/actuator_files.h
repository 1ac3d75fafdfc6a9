// The shipped design files, found from the source tree, for the actuators' tests.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "actuators/combination.h"
#include "actuators/design.h"
#include "datom/dimensions.h"

namespace datomsim::testing {

inline const std::filesystem::path kDesignDirectory =
    std::filesystem::path(DATOMSIM_SOURCE_DIR) / "data" / "actuators";

inline actuators::Design shippedDesign(const std::string& name) {
  auto design = actuators::loadDesign(kDesignDirectory, name);
  EXPECT_TRUE(design.ok()) << (design ? "" : design.error());
  return *design;
}

// A size: radius r (m) and t = r / 10, as the derived tables of docs/actuators.md.
inline datom::Dimensions sizeOf(double r) {
  return *datom::dimensionsFor(r, r / 10.0);
}

}  // namespace datomsim::testing
