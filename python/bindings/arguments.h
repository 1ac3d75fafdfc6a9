// Python's values as the command line's: every argument of the package's functions arrives as a
// Python object and is converted here, so that a value of the wrong type is refused naming the
// function, the argument and what it expected (TypeError: "run(): max_motions must be an
// integer, got float"), and a value out of range as datomsim.Error, never pybind11's "Unable to
// cast" nor a signal. The values are then checked by src/frontend, as the command line's are.
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "elastic/load_parameters.h"
#include "geometry/cell.h"

namespace datomsim::python {

namespace py = pybind11;

// Where an argument goes: the function as Python calls it ("run()") and the argument's name
// ("max_motions").
struct Argument {
  std::string function;
  std::string name;

  // "run(): max_motions"
  std::string named() const;
};

// "int", "str", "array of float64": what a value is, for messages.
std::string typeName(const py::handle& value);

// An integer (a Python int or a numpy integer, never a bool) from `low` to `high`.
int64_t integerArgument(const Argument& argument, const py::handle& value, int64_t low,
                        int64_t high);
// The same for unsigned values up to 2^64 - 1 (seeds).
uint64_t unsignedArgument(const Argument& argument, const py::handle& value);
// A finite or infinite number: a Python int or float, a numpy number, never a bool (the
// frontend's checks refuse what is not finite, naming the option).
double numberArgument(const Argument& argument, const py::handle& value);
bool booleanArgument(const Argument& argument, const py::handle& value);
std::string stringArgument(const Argument& argument, const py::handle& value);
// A str or an os.PathLike, as text.
std::string pathArgument(const Argument& argument, const py::handle& value);
std::optional<std::string> optionalString(const Argument& argument, const py::handle& value);

// A cell given as three integers (a tuple, a list, an integer array) or as the command line's
// text ("6,5,2", "(6,5,2)"); text is refused as the command line refuses it, naming `option`.
geometry::Cell cellArgument(const Argument& argument, const py::handle& value,
                            const std::string& option);
std::optional<geometry::Cell> optionalCell(const Argument& argument, const py::handle& value,
                                           const std::string& option);

// "on" or "off", as the command line's switches take them.
std::string onOff(bool on);
// Three numbers (x, y, z) as the command line's text "x,y,z".
std::string vectorText(const Argument& argument, const py::handle& value);
// The load model's parameters by their keywords, as `loads` and `run` take them.
std::vector<std::pair<std::string, double*>> loadParameterKeywords(elastic::LoadParameters& p);

}  // namespace datomsim::python
