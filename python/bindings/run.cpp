// datomsim.run(): a program run on a scene with the command line's options as keywords, checked
// by the frontend as `datomsim run`'s are (docs/python.md).
#include "run.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "arguments.h"
#include "frontend/actuators_json.h"
#include "frontend/energy_json.h"
#include "frontend/output_file.h"
#include "frontend/run_json.h"
#include "frontend/run_on_scene.h"
#include "frontend/usage_error.h"
#include "scene.h"

namespace datomsim::python {

using frontend::UsageError;
using geometry::Cell;

namespace {

// The designs shipped with the package: beside the build tree's (build/<flavour>/python/datomsim
// and build/<flavour>/share/datomsim/actuators) or an installed prefix's
// (PREFIX/lib/python3/dist-packages/datomsim and PREFIX/share/datomsim/actuators).
std::filesystem::path shippedDesigns() {
  const std::filesystem::path package =
      std::filesystem::path(
          py::module_::import("datomsim._core").attr("__file__").cast<std::string>())
          .parent_path();
  // frontend::actuatorDesignDirectory looks in DIR/../share and DIR/../../share.
  try {
    return frontend::actuatorDesignDirectory({}, package);
  } catch (const UsageError&) {
    return frontend::actuatorDesignDirectory({}, package.parent_path().parent_path());
  }
}

// A program parameter's value as `--param KEY=VALUE` gives it: a number, a string or a bool.
std::string parameterText(const std::string& key, const py::handle& value) {
  const Argument argument{"run()", "params' " + key};
  if (PyBool_Check(value.ptr())) return value.ptr() == Py_True ? "true" : "false";
  if (PyUnicode_Check(value.ptr())) return stringArgument(argument, value);
  if (PyLong_Check(value.ptr()) || PyFloat_Check(value.ptr())) {
    return py::str(value).cast<std::string>();
  }
  throw py::type_error(fmt::format("{} must be a number, a string or a bool, got {}",
                                   argument.named(), typeName(value)));
}

// One of run()'s keywords into the command line's arguments; false when `name` is none of
// them.
bool runKeyword(frontend::RunArguments& args, const std::string& name, const py::handle& value) {
  const Argument argument{"run()", name};
  if (name == "goal" || name == "start" || name == "root") {
    const Cell cell = cellArgument(argument, value, "--" + name);
    (name == "goal"    ? args.goal
     : name == "start" ? args.start
                       : args.root) = fmt::format("{},{},{}", cell.x, cell.y, cell.z);
  } else if (name == "rules" || name == "module" || name == "rolling") {
    (name == "rules"    ? args.rules.rules
     : name == "module" ? args.module
                        : args.rolling) = stringArgument(argument, value);
  } else if (name == "target") {
    args.target = pathArgument(argument, value);
  } else if (name == "attachment") {
    args.rules.attachment = onOff(booleanArgument(argument, value));
  } else if (name == "connectivity") {
    args.rules.connectivity = onOff(booleanArgument(argument, value));
    args.connectivityGiven = true;
  } else if (name == "seed") {
    args.seed = std::to_string(unsignedArgument(argument, value));
  } else if (name == "delay_ms" || name == "jitter_ms") {
    (name == "delay_ms" ? args.delayMs : args.jitterMs) = numberArgument(argument, value);
  } else if (name == "timeout" || name == "until") {
    (name == "timeout" ? args.timeoutS : args.untilS) = numberArgument(argument, value);
  } else if (name == "max_motions") {
    // The range is the frontend's (1 or more), with the command line's message.
    args.maxMotions = integerArgument(argument, value, INT64_MIN, INT64_MAX);
  } else if (name == "trace") {
    args.wantTrace = booleanArgument(argument, value);
  } else if (name == "load_region") {
    args.loadRegion = int(integerArgument(argument, value, INT32_MIN, INT32_MAX));
    args.loadOptionsGiven.push_back("--load-region");
  } else if (name == "gravity") {
    // True or "on", False or "off", or three numbers.
    if (PyBool_Check(value.ptr())) {
      args.gravity = value.ptr() == Py_True ? "on" : "off";
    } else if (PyUnicode_Check(value.ptr())) {
      args.gravity = stringArgument(argument, value);
    } else {
      args.gravity = vectorText(argument, value);
    }
  } else if (name == "actuators" || name == "size") {
    (name == "actuators" ? args.actuators : args.size) = stringArgument(argument, value);
    if (name == "size") args.actuatorOptionsGiven.emplace_back("--size");
  } else if (name == "designs") {
    args.actuatorDesigns = pathArgument(argument, value);
    args.actuatorOptionsGiven.emplace_back("--designs");
  } else if (name == "params") {
    if (!PyDict_Check(value.ptr())) {
      throw py::type_error(fmt::format("run(): params must be a dict, got {}", typeName(value)));
    }
    for (const auto& [key, item] : py::reinterpret_borrow<py::dict>(value)) {
      const std::string text = stringArgument({"run()", "a key of params"}, key);
      args.parameters.push_back(text + "=" + parameterText(text, item));
    }
  } else {
    return false;
  }
  return true;
}

}  // namespace

// (the JSON text of `run --out`, the trace or None, the failure or None).
std::tuple<std::string, std::optional<std::string>, std::optional<std::string>> run(
    const py::object& on, const py::object& name, const py::dict& options) {
  const Scene& scene = sceneArgument({"run()", "scene"}, on);
  frontend::RunArguments args;
  args.program = stringArgument({"run()", "program"}, name);
  std::optional<std::string> tracePath;
  std::optional<std::string> powerCsvPath;
  const std::vector<std::pair<std::string, double*>> loadNumbers =
      loadParameterKeywords(args.loads);
  std::string sceneName = scene.scene().name.value_or("a scene from Python");
  for (const auto& [key, value] : options) {
    const std::string option = stringArgument({"run()", "a keyword"}, key);
    if (value.is_none()) continue;
    const auto loadNumber = std::find_if(loadNumbers.begin(), loadNumbers.end(),
                                         [&](const auto& entry) { return entry.first == option; });
    if (loadNumber != loadNumbers.end()) {
      // The load model's, named as the command line's options for the shared refusals.
      *loadNumber->second = numberArgument({"run()", option}, value);
      std::string flag = "--" + option;
      std::replace(flag.begin(), flag.end(), '_', '-');
      args.loadOptionsGiven.push_back(flag);
    } else if (option == "scene_name") {
      sceneName = stringArgument({"run()", option}, value);
    } else if (option == "trace" && PyUnicode_Check(value.ptr())) {
      // A path: the file to write the trace to (True: its text returned, by runKeyword).
      tracePath = stringArgument({"run()", option}, value);
      if (tracePath->empty()) throw UsageError("run: trace is an empty file name");
      args.wantTrace = true;
    } else if (option == "power_csv") {
      // A file written as `run --power-csv` writes it, with the trace's checks.
      powerCsvPath = pathArgument({"run()", option}, value);
      if (powerCsvPath->empty()) throw UsageError("run: power_csv is an empty file name");
      args.actuatorOptionsGiven.emplace_back("--power-csv");
    } else if (!runKeyword(args, option, value)) {
      throw UsageError(
          fmt::format("run: unknown option {} (known: goal, start, rules, "
                      "attachment, connectivity, seed, delay_ms, jitter_ms, "
                      "max_motions, target, timeout, until, params, root, trace, module, "
                      "rolling, gravity, load_region, radius, thickness, density, "
                      "solid_fraction, young_modulus, poisson_ratio, latch_force, latch_moment, "
                      "actuators, size, designs, power_csv)",
                      option));
    }
  }
  if (!args.actuators.empty() && args.actuatorDesigns.empty()) {
    args.actuatorDesigns = shippedDesigns();
  }
  // The files checked against the scene's file, the target and the designs before the run, as
  // `run --trace` and `--power-csv` are.
  std::optional<frontend::CommandFiles> files;
  if (tracePath || powerCsvPath) {
    std::vector<frontend::NamedPath> inputs = inputsOf(scene);
    if (!args.target.empty()) inputs.push_back({"target", args.target});
    if (!args.actuatorDesigns.empty()) inputs.push_back({"designs", args.actuatorDesigns});
    std::vector<frontend::NamedPath> outputs;
    if (tracePath) outputs.push_back({"trace", *tracePath});
    if (powerCsvPath) outputs.push_back({"power_csv", *powerCsvPath});
    files.emplace(inputs, outputs);
  }
  frontend::RunOutput output = frontend::runOnScene(scene.scene(), sceneName, args);
  std::optional<std::string> trace;
  if (files) {
    if (tracePath) files->write("trace", output.result.trace);
    if (powerCsvPath && output.result.energy) {
      files->write("power_csv", frontend::powerCsv(*output.result.energy));
    }
    files->commit(frontend::Reporter(true));
  }
  if (!tracePath && args.wantTrace) trace = std::move(output.result.trace);
  return {frontend::runJson(output.kind.name, output.result), std::move(trace), output.failure};
}

}  // namespace datomsim::python
