// Which actuators a module carries: one deformation design and one latch design, written
// "DEFORMATION+LATCH" (`sma-spring+electrostatic-latch`; the latch may be named short:
// `sma-spring+electrostatic`). Design files are found by name in a folder of designs (the
// project's data/actuators, installed in PREFIX/share/datomsim/actuators).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "actuators/design.h"
#include "datomsim/result.h"

namespace datomsim::actuators {

struct Combination {
  std::string deformation;  // a design's full name, e.g. "sma-spring"
  std::string latch;        // a design's full name, e.g. "electrostatic-latch"
};

// The full name of one design named in full or, for a latch, short ("electrostatic"); an unknown
// name is refused with the closest known one suggested.
Result<std::string> designName(std::string_view name);

// Parses "DEFORMATION+LATCH" (either order). Refuses unknown names (with a suggestion), two
// designs of one kind, and anything but two names.
Result<Combination> parseCombination(std::string_view text);

// The known design nearest to `name` by edit distance (for "did you mean").
std::string closestDesignName(std::string_view name);

// Reads the design `name` (full or short) from `directory`/NAME.json, checking that the file's
// model is the one its name says.
Result<Design> loadDesign(const std::filesystem::path& directory, std::string_view name);

}  // namespace datomsim::actuators
