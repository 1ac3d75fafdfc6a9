// A cell as people type it, and lists of cells as messages print them: "x,y,z", also "(x,y,z)" as
// pictures and logs print cells, and with spaces around the numbers. One reading for the command
// line and program parameters alike.
#pragma once

#include <charconv>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "geometry/cell.h"

namespace datomsim::geometry {

inline std::string_view trimSpaces(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  return text;
}

// The cell, or nullopt unless the text is exactly three integers of 32 bits.
inline std::optional<Cell> cellFromText(std::string_view text) {
  text = trimSpaces(text);
  if (text.size() >= 2 && text.front() == '(' && text.back() == ')') {
    text = text.substr(1, text.size() - 2);
  }
  int32_t parts[3];
  for (int i = 0; i < 3; ++i) {
    const size_t comma = i < 2 ? text.find(',') : text.size();
    if (comma == std::string_view::npos) return std::nullopt;
    const std::string_view part = trimSpaces(text.substr(0, comma));
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), parts[i]);
    if (part.empty() || error != std::errc() || end != part.data() + part.size()) {
      return std::nullopt;
    }
    text = i < 2 ? text.substr(comma + 1) : std::string_view();
  }
  return Cell{parts[0], parts[1], parts[2]};
}

// "1,2,3 4,5,6 and 7 more": the first `named` cells of a list, for messages.
inline std::string cellList(std::span<const Cell> cells, size_t named = 12) {
  std::string text;
  for (size_t i = 0; i < cells.size() && i < named; ++i) {
    if (i) text += ' ';
    text += toString(cells[i]);
  }
  if (cells.size() > named) text += " and " + std::to_string(cells.size() - named) + " more";
  return text;
}

// Cells as words: "1,1,1", "1,1,1 and 1,0,1", "1,1,1, 1,0,1 and 2,0,1" (`last`: "and" or "or").
inline std::string cellsInWords(std::span<const Cell> cells, std::string_view last) {
  std::string text;
  for (size_t i = 0; i < cells.size(); ++i) {
    if (i > 0 && i + 1 < cells.size()) text += ", ";
    if (i > 0 && i + 1 == cells.size()) {
      text += ' ';
      text.append(last);
      text += ' ';
    }
    text += toString(cells[i]);
  }
  return text;
}

}  // namespace datomsim::geometry
