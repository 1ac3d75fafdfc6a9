#include "arguments.h"

#include <fmt/format.h>

#include <cmath>

#include "frontend/arguments.h"
#include "frontend/usage_error.h"

namespace datomsim::python {

using frontend::UsageError;

namespace {

bool isBoolean(const py::handle& value) {
  // numpy's bool_ is no int subclass, but it has __index__ in older numpy: named to refuse it.
  return PyBool_Check(value.ptr()) || typeName(value) == "bool_";
}

// A short repr for messages: a hostile value may be megabytes long.
std::string shortRepr(const py::handle& value) {
  std::string text;
  try {
    text = py::repr(value).cast<std::string>();
  } catch (const py::error_already_set&) {
    return "?";
  }
  constexpr size_t kLongest = 60;
  if (text.size() <= kLongest) return text;
  // Cut between UTF-8 characters: half a character made the message invalid UTF-8, which Python
  // could not decode, and the TypeError came without a message.
  size_t cut = kLongest;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return text.substr(0, cut) + "...";
}

// The integer a value stands for (an int or a numpy integer), or nothing.
std::optional<py::int_> integerOf(const py::handle& value) {
  if (isBoolean(value) || !PyIndex_Check(value.ptr())) return std::nullopt;
  PyObject* index = PyNumber_Index(value.ptr());
  if (index == nullptr) {
    PyErr_Clear();
    return std::nullopt;
  }
  return py::reinterpret_steal<py::int_>(index);
}

}  // namespace

std::string Argument::named() const {
  return fmt::format("{}: {}", function, name);
}

std::string typeName(const py::handle& value) {
  const py::handle type = py::type::of(value);
  const std::string name = py::str(type.attr("__name__")).cast<std::string>();
  if (name == "ndarray" && py::hasattr(value, "dtype")) {
    return "array of " + py::str(value.attr("dtype")).cast<std::string>();
  }
  return name;
}

int64_t integerArgument(const Argument& argument, const py::handle& value, int64_t low,
                        int64_t high) {
  const std::optional<py::int_> integer = integerOf(value);
  if (!integer) {
    throw py::type_error(
        fmt::format("{} must be an integer, got {}", argument.named(), typeName(value)));
  }
  int overflow = 0;
  const long long got = PyLong_AsLongLongAndOverflow(integer->ptr(), &overflow);
  if (overflow != 0 || got < low || got > high) {
    throw UsageError(fmt::format("{} {}: an integer from {} to {}", argument.named(),
                                 py::repr(*integer).cast<std::string>(), low, high));
  }
  return got;
}

uint64_t unsignedArgument(const Argument& argument, const py::handle& value) {
  const std::optional<py::int_> integer = integerOf(value);
  if (!integer) {
    throw py::type_error(
        fmt::format("{} must be an integer, got {}", argument.named(), typeName(value)));
  }
  // Checked as the command line checks a seed, with its message.
  return frontend::parseSeed("--" + argument.name, py::repr(*integer).cast<std::string>());
}

double numberArgument(const Argument& argument, const py::handle& value) {
  if (isBoolean(value) || PyUnicode_Check(value.ptr()) || !PyNumber_Check(value.ptr())) {
    throw py::type_error(
        fmt::format("{} must be a number, got {}", argument.named(), typeName(value)));
  }
  const double number = PyFloat_AsDouble(value.ptr());
  if (number == -1.0 && PyErr_Occurred()) {
    const bool tooLarge = PyErr_ExceptionMatches(PyExc_OverflowError) != 0;
    PyErr_Clear();
    if (tooLarge) {
      throw UsageError(
          fmt::format("{} {}: too large a number", argument.named(), shortRepr(value)));
    }
    throw py::type_error(
        fmt::format("{} must be a number, got {}", argument.named(), typeName(value)));
  }
  return number;
}

bool booleanArgument(const Argument& argument, const py::handle& value) {
  if (!isBoolean(value)) {
    throw py::type_error(
        fmt::format("{} must be True or False, got {}", argument.named(), typeName(value)));
  }
  return PyObject_IsTrue(value.ptr()) == 1;
}

std::string stringArgument(const Argument& argument, const py::handle& value) {
  if (!PyUnicode_Check(value.ptr())) {
    throw py::type_error(
        fmt::format("{} must be a string, got {}", argument.named(), typeName(value)));
  }
  Py_ssize_t size = 0;
  const char* text = PyUnicode_AsUTF8AndSize(value.ptr(), &size);
  if (text == nullptr) {
    PyErr_Clear();
    throw UsageError(fmt::format("{} {}: not text UTF-8 can hold (a lone surrogate)",
                                 argument.named(), shortRepr(value)));
  }
  return std::string(text, size_t(size));
}

std::string pathArgument(const Argument& argument, const py::handle& value) {
  if (PyUnicode_Check(value.ptr())) return stringArgument(argument, value);
  if (py::hasattr(value, "__fspath__")) {
    const py::object path = py::module_::import("os").attr("fspath")(value);
    if (PyUnicode_Check(path.ptr())) return stringArgument(argument, path);
  }
  throw py::type_error(fmt::format("{} must be a path (a str or an os.PathLike), got {}",
                                   argument.named(), typeName(value)));
}

std::optional<std::string> optionalString(const Argument& argument, const py::handle& value) {
  if (value.is_none()) return std::nullopt;
  return stringArgument(argument, value);
}

geometry::Cell cellArgument(const Argument& argument, const py::handle& value,
                            const std::string& option) {
  if (PyUnicode_Check(value.ptr())) {
    return frontend::parseCell(option, stringArgument(argument, value));
  }
  const auto refuse = [&] {
    return py::type_error(fmt::format("{} must be three integers x,y,z, got {} {}",
                                      argument.named(), typeName(value), shortRepr(value)));
  };
  if (!PySequence_Check(value.ptr()) || PyBytes_Check(value.ptr()) ||
      PySequence_Size(value.ptr()) != 3) {
    PyErr_Clear();
    throw refuse();
  }
  std::string text;
  for (Py_ssize_t k = 0; k < 3; ++k) {
    const py::object item = py::reinterpret_steal<py::object>(PySequence_GetItem(value.ptr(), k));
    if (!item) {
      PyErr_Clear();
      throw refuse();
    }
    const std::optional<py::int_> integer = integerOf(item);
    if (!integer) throw refuse();
    text += (k ? "," : "") + py::repr(*integer).cast<std::string>();
  }
  // The command line's range check and message.
  return frontend::parseCell(option, text);
}

std::optional<geometry::Cell> optionalCell(const Argument& argument, const py::handle& value,
                                           const std::string& option) {
  if (value.is_none()) return std::nullopt;
  return cellArgument(argument, value, option);
}

std::string onOff(bool on) {
  return on ? "on" : "off";
}

// The load model's parameters by their keywords, as `loads` and `run` take them.
std::vector<std::pair<std::string, double*>> loadParameterKeywords(elastic::LoadParameters& p) {
  return {{"radius", &p.radius},
          {"thickness", &p.thickness},
          {"density", &p.density},
          {"solid_fraction", &p.solidFraction},
          {"young_modulus", &p.youngModulus},
          {"poisson_ratio", &p.poissonRatio},
          {"latch_force", &p.latchForce},
          {"latch_moment", &p.latchMoment}};
}

// Three numbers (x, y, z) as the command line's text "x,y,z".
std::string vectorText(const Argument& argument, const py::handle& value) {
  if (PyUnicode_Check(value.ptr()) || !PySequence_Check(value.ptr()) ||
      PySequence_Size(value.ptr()) != 3) {
    PyErr_Clear();
    throw py::type_error(fmt::format("{} must be three numbers (x, y, z), m/s^2, got {}",
                                     argument.named(), typeName(value)));
  }
  const py::sequence parts = py::reinterpret_borrow<py::sequence>(value);
  return fmt::format("{},{},{}", numberArgument(argument, parts[0]),
                     numberArgument(argument, parts[1]), numberArgument(argument, parts[2]));
}

}  // namespace datomsim::python
