// Parameters as text, checked once against the program's declaration, then read typed.
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "datomsim/parameters.h"
#include "geometry/cell_text.h"

namespace datomsim {

namespace {

template <typename Number>
std::optional<Number> parseNumber(std::string_view text) {
  text = geometry::trimSpaces(text);
  Number value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) {
    return std::nullopt;
  }
  return value;
}

std::optional<bool> parseFlag(std::string_view text) {
  text = geometry::trimSpaces(text);
  for (const std::string_view yes : {"true", "on", "yes", "1"}) {
    if (text == yes) return true;
  }
  for (const std::string_view no : {"false", "off", "no", "0"}) {
    if (text == no) return false;
  }
  return std::nullopt;
}

std::string_view article(Parameter::Type type) {
  return type == Parameter::Type::kInteger ? "an" : "a";
}

std::string example(Parameter::Type type) {
  switch (type) {
    case Parameter::Type::kInteger:
      return "42";
    case Parameter::Type::kNumber:
      return "0.5";
    case Parameter::Type::kFlag:
      return "true";
    case Parameter::Type::kCell:
      return "X,Y,Z";
    case Parameter::Type::kText:
      return "TEXT";
  }
  return "?";
}

}  // namespace

std::string_view toString(Parameter::Type type) {
  switch (type) {
    case Parameter::Type::kInteger:
      return "integer";
    case Parameter::Type::kNumber:
      return "number";
    case Parameter::Type::kFlag:
      return "flag";
    case Parameter::Type::kCell:
      return "cell";
    case Parameter::Type::kText:
      return "text";
  }
  return "?";
}

Result<Parameters> Parameters::check(std::string_view program,
                                     const std::vector<Parameter>& declared,
                                     const std::map<std::string, std::string>& given) {
  for (const auto& [name, value] : given) {
    bool known = false;
    for (const Parameter& parameter : declared) known = known || parameter.name == name;
    if (known) continue;
    std::string names;
    for (const Parameter& parameter : declared)
      names += (names.empty() ? "" : ", ") + parameter.name;
    return Error{fmt::format("program {} has no parameter \"{}\" ({})", program, name,
                             names.empty() ? "it takes none" : "its parameters: " + names)};
  }

  Parameters parameters;
  for (const Parameter& parameter : declared) {
    const auto found = given.find(parameter.name);
    if (found == given.end() && parameter.defaultValue.empty()) {
      return Error{fmt::format("program {} needs parameter {}, {} {} ({}): --param {}={}", program,
                               parameter.name, article(parameter.type), toString(parameter.type),
                               parameter.help, parameter.name, example(parameter.type))};
    }
    const std::string& text = found != given.end() ? found->second : parameter.defaultValue;
    const auto bad = [&](const std::string& why) {
      return Error{
          fmt::format("parameter {} of program {}: \"{}\" {}", parameter.name, program, text, why)};
    };
    Value value;
    value.type = parameter.type;
    value.given = found != given.end();
    double numeric = 0;
    switch (parameter.type) {
      case Parameter::Type::kInteger: {
        const auto parsed = parseNumber<int64_t>(text);
        if (!parsed) return bad("is not an integer");
        value.integer = *parsed;
        numeric = double(*parsed);
        break;
      }
      case Parameter::Type::kNumber: {
        const auto parsed = parseNumber<double>(text);
        if (!parsed || !std::isfinite(*parsed)) return bad("is not a finite number");
        value.number = *parsed;
        numeric = *parsed;
        break;
      }
      case Parameter::Type::kFlag: {
        const auto parsed = parseFlag(text);
        if (!parsed) return bad("is not a flag (true or false)");
        value.integer = *parsed ? 1 : 0;
        break;
      }
      case Parameter::Type::kCell: {
        const auto parsed = geometry::cellFromText(text);
        if (!parsed) return bad("is not a cell x,y,z of three integers");
        value.cell = *parsed;
        break;
      }
      case Parameter::Type::kText:
        break;
    }
    if ((parameter.min && numeric < *parameter.min) ||
        (parameter.max && numeric > *parameter.max)) {
      return bad(fmt::format("is out of its range, {} to {}", parameter.min.value_or(-INFINITY),
                             parameter.max.value_or(INFINITY)));
    }
    parameters.values_[parameter.name] = value;
    parameters.text_[parameter.name] = text;
  }
  return parameters;
}

const Parameters::Value& Parameters::find(std::string_view name, Parameter::Type type) const {
  const auto found = values_.find(name);
  if (found == values_.end()) {
    throw std::logic_error(
        fmt::format("the program asks for parameter \"{}\", which it did not "
                    "declare",
                    name));
  }
  if (found->second.type != type) {
    throw std::logic_error(
        fmt::format("the program reads parameter {} as {} {}, but declared it "
                    "{} {}",
                    name, article(type), toString(type), article(found->second.type),
                    toString(found->second.type)));
  }
  return found->second;
}

int64_t Parameters::integer(std::string_view name) const {
  return find(name, Parameter::Type::kInteger).integer;
}

double Parameters::number(std::string_view name) const {
  return find(name, Parameter::Type::kNumber).number;
}

bool Parameters::flag(std::string_view name) const {
  return find(name, Parameter::Type::kFlag).integer != 0;
}

Cell Parameters::cell(std::string_view name) const {
  return find(name, Parameter::Type::kCell).cell;
}

const std::string& Parameters::text(std::string_view name) const {
  find(name, Parameter::Type::kText);
  return text_.find(name)->second;
}

bool Parameters::given(std::string_view name) const {
  const auto found = values_.find(name);
  return found != values_.end() && found->second.given;
}

}  // namespace datomsim
