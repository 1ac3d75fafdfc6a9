// datomsim.run()'s C++ half: the options as the command line's, the run, its files.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <tuple>

namespace datomsim::python {

namespace py = pybind11;

// (the JSON text of `run --out`, the trace or None, the failure or None). `options` are run()'s
// keywords (datomsim/__init__.py); a bad one raises datomsim.Error with the command line's
// message, a file asked for (trace, power_csv) is written whole or not at all.
std::tuple<std::string, std::optional<std::string>, std::optional<std::string>> run(
    const py::object& on, const py::object& name, const py::dict& options);

}  // namespace datomsim::python
