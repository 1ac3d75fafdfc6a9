// Numbers as text, the way the scene files write them: comma-separated lists such as VisibleSim's
// position="1,2,0", and the shortest decimal form of a double that reads back to the same value.
//
// Parsing is strict (no trailing characters, no empty components) so that a typo in a file is
// reported instead of silently read as something else. Formatting is locale-free and identical on
// every platform, which keeps written files byte for byte deterministic.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace datomsim::io {

// The integers of "a,b,c" (spaces around a component are allowed); nullopt if any component is
// not a decimal integer that fits in 64 bits.
std::optional<std::vector<int64_t>> parseIntegerList(std::string_view text);

// The numbers of "a,b,c" (decimal or exponent notation); nullopt if any component is not a finite
// number.
std::optional<std::vector<double>> parseNumberList(std::string_view text);

// Appends an integer in decimal.
void appendInteger(std::string& out, int64_t value);

// The shortest decimal text that reads back to exactly `value` ("10", "2.5", "1e+20").
std::string formatNumber(double value);

}  // namespace datomsim::io
