// How deep a JSON text nests, found by scanning its brackets outside strings, before any parser
// or printer walks it recursively: a value of tens of thousands of '[' would exhaust the stack.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace datomsim {

// The line (from 1) where the text first nests deeper than `limit` levels, if it does.
inline std::optional<int> lineNestedDeeperThan(std::string_view text, int limit) {
  int depth = 0;
  int line = 1;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') ++line;
    if (inString) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        inString = false;
      }
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return line;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return std::nullopt;
}

}  // namespace datomsim
