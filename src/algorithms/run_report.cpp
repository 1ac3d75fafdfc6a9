#include "algorithms/run_report.h"

namespace datomsim::algorithms {

std::vector<geometry::Cell> RunReport::cells(std::string_view key) const {
  const auto* found = find<std::vector<geometry::Cell>>(key);
  return found ? *found : std::vector<geometry::Cell>{};
}

RunReport::CellInts RunReport::cellInts(std::string_view key) const {
  const auto* found = find<CellInts>(key);
  return found ? *found : CellInts{};
}

std::vector<RunReport::Record> RunReport::records(std::string_view key) const {
  const auto* found = find<std::vector<Record>>(key);
  return found ? *found : std::vector<Record>{};
}

std::optional<bool> RunReport::flag(std::string_view key) const {
  const auto* found = find<bool>(key);
  return found ? std::optional<bool>(*found) : std::nullopt;
}

std::vector<std::pair<geometry::Cell, double>> RunReport::cellValues(std::string_view key) const {
  std::vector<std::pair<geometry::Cell, double>> out;
  if (const auto* streamed = find<Streamed>(key)) {
    (*streamed)([&](const geometry::Cell& cell, double value) { out.push_back({cell, value}); });
  }
  return out;
}

}  // namespace datomsim::algorithms
