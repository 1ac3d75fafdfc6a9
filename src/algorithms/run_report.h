// What a program reports after its run: named sections, in the order the run's JSON output writes
// them (docs/file-formats.md, "Run results"). The programs fill it without knowing JSON; the front
// end writes each section by the kind of its value, and tests read them back by name.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "geometry/cell.h"

namespace datomsim::algorithms {

class RunReport {
 public:
  // One value of a record: null, a flag, a whole number, a number or a text.
  using Scalar = std::variant<std::monostate, bool, int64_t, double, std::string>;
  // Named values in order (a JSON object).
  using Record = std::vector<std::pair<std::string, Scalar>>;
  // A value for some cells, given cell by cell as they are read: a million modules' values are
  // never gathered in one list.
  using CellValue = std::function<void(const geometry::Cell&, double)>;
  using Streamed = std::function<void(const CellValue&)>;
  using CellInts = std::vector<std::pair<geometry::Cell, int>>;
  using Value = std::variant<bool, Record, std::vector<Record>, std::vector<geometry::Cell>,
                             CellInts, Streamed>;

  struct Section {
    std::string key;
    Value value;
  };

  // Text values by name as a record: a program's parameters as given.
  static Record recordOf(const std::map<std::string, std::string>& texts) {
    Record record;
    for (const auto& [name, text] : texts) record.push_back({name, text});
    return record;
  }

  void add(std::string key, Value value) {
    sections_.push_back({std::move(key), std::move(value)});
  }
  const std::vector<Section>& sections() const { return sections_; }

  // The value of a section, if there is one of that key and kind.
  template <typename T>
  const T* find(std::string_view key) const {
    for (const Section& section : sections_) {
      if (section.key == key) return std::get_if<T>(&section.value);
    }
    return nullptr;
  }
  // The same, empty (or false) where there is none: for tests and small callers.
  std::vector<geometry::Cell> cells(std::string_view key) const;
  CellInts cellInts(std::string_view key) const;
  std::vector<Record> records(std::string_view key) const;
  std::optional<bool> flag(std::string_view key) const;
  // A streamed section gathered in one list.
  std::vector<std::pair<geometry::Cell, double>> cellValues(std::string_view key) const;
  // The field of a record, if it has one of that kind.
  template <typename T>
  static const T* field(const Record& record, std::string_view name) {
    for (const auto& [key, value] : record) {
      if (key == name) return std::get_if<T>(&value);
    }
    return nullptr;
  }

 private:
  std::vector<Section> sections_;
};

}  // namespace datomsim::algorithms
