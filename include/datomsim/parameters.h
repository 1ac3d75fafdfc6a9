// A program's parameters: declared by the program with their types, given on the command line
// (`--param key=value`, repeatable) or in the scene file ("parameters": {"PROGRAM": {...}}), and
// checked before the run starts, so that a bad key or value stops the run with a message naming
// it (docs/writing-programs.md, "Parameters").
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "datomsim/cell.h"
#include "datomsim/export.h"
#include "datomsim/result.h"

namespace datomsim {

struct Parameter {
  enum class Type : uint8_t {
    kInteger,  // 42
    kNumber,   // 0.25
    kFlag,     // true | false (also on | off, yes | no, 1 | 0)
    kCell,     // x,y,z
    kText,     // anything
  };

  std::string name;
  Type type = Type::kText;
  // One line for --help and error messages.
  std::string help;
  // Written as on the command line; empty: the parameter must be given.
  std::string defaultValue;
  // For integers and numbers: the allowed range, both ends included.
  std::optional<double> min;
  std::optional<double> max;
  // For cells: the cell must hold a module of the scene (a root, a leader...). Every cell must
  // lie inside the world.
  bool holdsModule = false;

  static Parameter integer(std::string name, std::string help, std::string defaultValue = {}) {
    return make(Type::kInteger, std::move(name), std::move(help), std::move(defaultValue));
  }
  static Parameter number(std::string name, std::string help, std::string defaultValue = {}) {
    return make(Type::kNumber, std::move(name), std::move(help), std::move(defaultValue));
  }
  static Parameter flag(std::string name, std::string help, std::string defaultValue = "false") {
    return make(Type::kFlag, std::move(name), std::move(help), std::move(defaultValue));
  }
  static Parameter cell(std::string name, std::string help, std::string defaultValue = {}) {
    return make(Type::kCell, std::move(name), std::move(help), std::move(defaultValue));
  }
  static Parameter text(std::string name, std::string help, std::string defaultValue = {}) {
    return make(Type::kText, std::move(name), std::move(help), std::move(defaultValue));
  }
  // The range of an integer or a number: Parameter::integer("steps", "...", "10").range(1, 1000).
  Parameter range(double low, double high) && {
    min = low;
    max = high;
    return std::move(*this);
  }
  // A cell that must hold a module: Parameter::cell("root", "...").module().
  Parameter module() && {
    holdsModule = true;
    return std::move(*this);
  }

 private:
  static Parameter make(Type type, std::string name, std::string help, std::string defaultValue) {
    Parameter parameter;
    parameter.name = std::move(name);
    parameter.type = type;
    parameter.help = std::move(help);
    parameter.defaultValue = std::move(defaultValue);
    return parameter;
  }
};

// "integer", "number", "flag", "cell", "text".
DATOMSIM_API std::string_view toString(Parameter::Type type);

// The checked values of a program's parameters, every declared one present (given or default).
// Asking for a name the program did not declare, or with another type, is a programming error of
// the program: it throws std::logic_error naming the parameter.
class DATOMSIM_API Parameters {
 public:
  Parameters() = default;

  // Checks `given` (name -> value as text) against the declarations of program `program`: an
  // unknown name, a value that is not of its type or out of its range, or a missing required
  // parameter is refused with a message naming it.
  static Result<Parameters> check(std::string_view program, const std::vector<Parameter>& declared,
                                  const std::map<std::string, std::string>& given);

  int64_t integer(std::string_view name) const;
  double number(std::string_view name) const;
  bool flag(std::string_view name) const;
  Cell cell(std::string_view name) const;
  const std::string& text(std::string_view name) const;
  // Whether the value was given (on the command line or in the scene) rather than defaulted.
  bool given(std::string_view name) const;

  // Every parameter as text, by name (what the run's JSON output records).
  const std::map<std::string, std::string, std::less<>>& values() const { return text_; }

 private:
  struct Value {
    Parameter::Type type = Parameter::Type::kText;
    int64_t integer = 0;
    double number = 0;
    Cell cell;
    bool given = false;
  };
  const Value& find(std::string_view name, Parameter::Type type) const;

  std::map<std::string, Value, std::less<>> values_;
  std::map<std::string, std::string, std::less<>> text_;
};

}  // namespace datomsim
