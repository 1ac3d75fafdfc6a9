// datomsim._core: the Python package's C++ half (docs/python.md). It drives the services the
// command line's subcommands drive (src/frontend: runOnScene, reachOnScene, movesJson), so that a
// run from Python gives the JSON `run --out` gives, and a refusal the same message, raised as
// datomsim.Error. Arrays (cells, distances, colours) are numpy arrays; the rest is what
// datomsim/__init__.py shapes into Python values.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <fmt/format.h>
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "frontend/arguments.h"
#include "frontend/geometry_json.h"
#include "frontend/loads_on_scene.h"
#include "frontend/motion_json.h"
#include "frontend/reach_on_scene.h"
#include "frontend/reshape_case.h"
#include "frontend/run_json.h"
#include "frontend/run_on_scene.h"
#include "frontend/usage_error.h"
#include "geometry/cell_text.h"
#include "io/scene_file.h"
#include "motion/motion.h"
#include "scene.h"
#include "scene/box.h"
#include "scene/paper_arch.h"
#include "scene/random_scene.h"

namespace py = pybind11;

namespace datomsim::python {
namespace {

using frontend::UsageError;
using geometry::Cell;

std::string onOff(bool on) {
  return on ? "on" : "off";
}

const Scene& sceneArgument(const Argument& argument, const py::object& value) {
  if (!py::isinstance<Scene>(value)) {
    throw py::type_error(
        fmt::format("{} must be a datomsim.Scene, got {}", argument.named(), typeName(value)));
  }
  return value.cast<const Scene&>();
}

// The module, its rules and rolls as reach and moves take them, checked by the frontend as the
// command line's options are.
frontend::MotionChoice motionChoice(const std::string& function, const Scene& scene,
                                    const py::object& rules, const py::object& attachment,
                                    const py::object& connectivity, const py::object& module,
                                    const py::object& rolling) {
  frontend::RuleArguments arguments;
  arguments.rules = stringArgument({function, "rules"}, rules);
  arguments.attachment = onOff(booleanArgument({function, "attachment"}, attachment));
  arguments.connectivity = onOff(booleanArgument({function, "connectivity"}, connectivity));
  const std::string rolls = stringArgument({function, "rolling"}, rolling);
  const auto rollRules = catom3d::rollRulesNamed(rolls);
  if (!rollRules) throw UsageError("--rolling: " + rolls + " not in {symmetric,visiblesim}");
  return {kindOf(optionalString({function, "module"}, module), scene.scene().moduleKind),
          arguments.options(), *rollRules};
}

// {"cells": (n, 3), "distances": (n,), "path": (p, 3), "goal": (3,)}: `reach --out` as arrays.
py::dict reach(const py::object& on, const py::object& goal, const py::object& start,
               const py::object& rules, const py::object& attachment,
               const py::object& connectivity, const py::object& module,
               const py::object& rolling) {
  const Scene& scene = sceneArgument({"reach()", "scene"}, on);
  const Cell at = cellArgument({"reach()", "goal"}, goal, "--goal");
  const std::optional<Cell> from = optionalCell({"reach()", "start"}, start, "--start");
  const frontend::MotionChoice model =
      motionChoice("reach()", scene, rules, attachment, connectivity, module, rolling);
  const frontend::ReachOutput reached = frontend::reachOnScene(scene.scene(), at, from, model);
  const auto sorted = reached.map.sorted();
  std::vector<Cell> cells;
  py::array_t<int32_t> distances{py::ssize_t(sorted.size())};
  auto view = distances.mutable_unchecked<1>();
  cells.reserve(sorted.size());
  for (size_t k = 0; k < sorted.size(); ++k) {
    cells.push_back(sorted[k].first);
    view(py::ssize_t(k)) = sorted[k].second;
  }
  py::dict out;
  out["goal"] = py::make_tuple(at.x, at.y, at.z);
  out["cells"] = cellArray(cells);
  out["distances"] = distances;
  out["path"] = cellArray(reached.path);
  return out;
}

// The JSON text of `moves --out`.
std::string moves(const py::object& on, const py::object& at, const py::object& rules,
                  const py::object& attachment, const py::object& module,
                  const py::object& rolling) {
  const Scene& scene = sceneArgument({"moves()", "scene"}, on);
  const Cell cell = cellArgument({"moves()", "at"}, at, "--at");
  const world::World& world = scene.scene().world;
  if (!world.isInside(cell)) {
    throw UsageError("--at " + geometry::toString(cell) + " " + world.bounds().whyOutside(cell));
  }
  const world::Module* mobile = world.moduleAt(cell);
  const motion::Mobile where{cell, mobile ? std::optional(mobile->id) : std::nullopt};
  const frontend::MotionChoice model =
      motionChoice("moves()", scene, rules, attachment, py::bool_(false), module, rolling);
  if (model.kind == world::ModuleKind::kCatom3D) {
    const catom3d::RollTable rolls;
    return frontend::rollsJson(cell, catom3d::evaluateAll(world, rolls, where, model.rolling),
                               model);
  }
  const motion::RuleTable table;
  return frontend::movesJson(cell, motion::evaluateAll(world, table, where, model.datom));
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

// The file a scene was read from, when it was: no output may overwrite it.
std::vector<frontend::NamedPath> inputsOf(const Scene& scene) {
  if (scene.source().empty()) return {};
  return {{"scene", scene.source()}};
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

// The JSON text of `loads --out`; the pictures asked for written as the command writes them.
std::string loads(const py::object& on, const py::dict& options) {
  const Scene& scene = sceneArgument({"loads()", "scene"}, on);
  frontend::LoadsArguments args;
  elastic::LoadParameters& p = args.parameters;
  const std::vector<std::pair<std::string, double*>> numbers = loadParameterKeywords(p);
  std::string solver = "auto";
  // The pictures' title names the scene: the command line gives its path.
  std::string title = scene.scene().name.value_or("scene");
  for (const auto& [key, value] : options) {
    const std::string name = key.cast<std::string>();
    if (value.is_none()) continue;
    const auto number = std::find_if(numbers.begin(), numbers.end(),
                                     [&](const auto& entry) { return entry.first == name; });
    if (number != numbers.end()) {
      *number->second = numberArgument({"loads()", name}, value);
    } else if (name == "gravity") {
      // Checked as the command line checks --gravity, with its message.
      p.gravity = frontend::parseVector("--gravity", vectorText({"loads()", "gravity"}, value));
    } else if (name == "top") {
      args.top = int(integerArgument({"loads()", "top"}, value, INT32_MIN, INT32_MAX));
    } else if (name == "view" || name == "solver" || name == "png" || name == "svg" ||
               name == "name") {
      const std::string text = stringArgument({"loads()", name}, value);
      if (name == "view") args.view = text;
      if (name == "solver") solver = text;
      if (name == "png") args.png = text;
      if (name == "svg") args.svg = text;
      if (name == "name") title = text;
    } else {
      throw UsageError(fmt::format(
          "loads: unknown option {} (known: radius, thickness, density, solid_fraction, "
          "young_modulus, poisson_ratio, latch_force, latch_moment, gravity, solver, top, view, "
          "png, svg, name)",
          name));
    }
  }
  if (args.view != "side" && args.view != "top") {
    throw UsageError("--view: " + args.view + " not in {side,top}");
  }
  if (solver != "auto" && solver != "direct" && solver != "iterative") {
    throw UsageError("--solver: " + solver + " not in {auto,direct,iterative}");
  }
  args.method = solver == "direct"      ? mechanics::SolverMethod::kDirect
                : solver == "iterative" ? mechanics::SolverMethod::kIterative
                                        : mechanics::SolverMethod::kAutomatic;
  std::vector<frontend::NamedPath> outputs;
  frontend::addLoadPictureOutputs(args, outputs);
  frontend::CommandFiles files(inputsOf(scene), outputs);
  // A scene describes its rest state: every pair of neighbours latched.
  world::World world = scene.scene().world;
  world.latchAllNeighbours();
  const frontend::LoadsOutput output = frontend::loadsOnScene(world, args);
  frontend::writeLoadPictures(output, args, title, files);
  files.commit(frontend::Reporter(true));
  return frontend::loadsJson(output);
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

// (the JSON text of `run --out`, the trace or None, the failure or None).
std::tuple<std::string, std::optional<std::string>, std::optional<std::string>> run(
    const py::object& on, const py::object& name, const py::dict& options) {
  const Scene& scene = sceneArgument({"run()", "scene"}, on);
  frontend::RunArguments args;
  args.program = stringArgument({"run()", "program"}, name);
  std::optional<std::string> tracePath;
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
    } else if (!runKeyword(args, option, value)) {
      throw UsageError(
          fmt::format("run: unknown option {} (known: goal, start, rules, "
                      "attachment, connectivity, seed, delay_ms, jitter_ms, "
                      "max_motions, target, timeout, until, params, root, trace, module, "
                      "rolling, gravity, load_region, radius, thickness, density, "
                      "solid_fraction, young_modulus, poisson_ratio, latch_force, latch_moment)",
                      option));
    }
  }
  // The trace file checked against the scene's file and the target before the run, as `run
  // --trace` is.
  std::optional<frontend::CommandFiles> files;
  if (tracePath) {
    std::vector<frontend::NamedPath> inputs = inputsOf(scene);
    if (!args.target.empty()) inputs.push_back({"target", args.target});
    files.emplace(inputs, std::vector<frontend::NamedPath>{{"trace", *tracePath}});
  }
  frontend::RunOutput output = frontend::runOnScene(scene.scene(), sceneName, args);
  std::optional<std::string> trace;
  if (files) {
    files->write("trace", output.result.trace);
    files->commit(frontend::Reporter(true));
  } else if (args.wantTrace) {
    trace = std::move(output.result.trace);
  }
  return {frontend::runJson(output.kind.name, output.result), std::move(trace), output.failure};
}

// The JSON text of `geometry --json`; a fraction outside 0..1 refused as the option is.
std::string geometryOf(const py::object& radiusValue, const py::object& thicknessValue,
                       const py::object& fractionValue) {
  const double radius = numberArgument({"geometry()", "radius"}, radiusValue);
  const double thickness = numberArgument({"geometry()", "thickness"}, thicknessValue);
  std::optional<double> fraction;
  if (!fractionValue.is_none())
    fraction = numberArgument({"geometry()", "fraction"}, fractionValue);
  if (fraction && !(*fraction >= 0 && *fraction <= 1)) {
    throw UsageError(fmt::format("--fraction: Value {} not in range [0 - 1]", *fraction));
  }
  return frontend::geometryJson(radius, thickness, fraction).dump();
}

Scene box(const py::object& size, const py::object& origin, const py::object& upright) {
  scene::BoxOptions options;
  options.origin = cellArgument({"box()", "origin"}, origin, "--origin");
  options.upright = booleanArgument({"box()", "upright"}, upright);
  const geometry::Cell cells = cellArgument({"box()", "size"}, size, "--size");
  return sceneOf(frontend::unwrap(scene::box(cells, options)),
                 fmt::format("box {}x{}x{}", cells.x, cells.y, cells.z));
}

Scene randomScene(const py::object& countValue, const py::object& seedValue,
                  const py::object& grid) {
  scene::RandomOptions options;
  options.gridSize = optionalCell({"random_scene()", "grid"}, grid, "--grid");
  const auto count = size_t(integerArgument({"random_scene()", "count"}, countValue, 0, INT64_MAX));
  const uint64_t seed = unsignedArgument({"random_scene()", "seed"}, seedValue);
  return sceneOf(frontend::unwrap(scene::random(seed, count, options)),
                 fmt::format("random, {} modules, seed {}", count, seed));
}

// A reshape case's floor: two integers (or the command line's text "X,Y").
std::string floorText(const py::object& floor) {
  const Argument argument{"reshape()", "floor"};
  if (PyUnicode_Check(floor.ptr())) return stringArgument(argument, floor);
  if (!PySequence_Check(floor.ptr()) || PySequence_Size(floor.ptr()) != 2) {
    PyErr_Clear();
    throw py::type_error(
        fmt::format("reshape(): floor must be two integers (x, y), got {}", typeName(floor)));
  }
  const py::sequence sides = py::reinterpret_borrow<py::sequence>(floor);
  const geometry::Cell size =
      cellArgument(argument, py::make_tuple(sides[0], sides[1], 1), "--floor");
  return fmt::format("{},{}", size.x, size.y);
}

Scene reshape(const py::object& kase, const py::object& length, const py::object& floor,
              const py::object& modules, const py::object& seed, const py::object& side,
              const py::object& base, const py::object& height) {
  const auto integer = [](const char* name, const py::object& value) {
    return int(integerArgument({"reshape()", name}, value, INT32_MIN, INT32_MAX));
  };
  frontend::ReshapeArguments args;
  args.kase = stringArgument({"reshape()", "case"}, kase);
  args.length = integer("length", length);
  args.floor = floorText(floor);
  args.modules = integer("modules", modules);
  args.seed = std::to_string(unsignedArgument({"reshape()", "seed"}, seed));
  args.side = integer("side", side);
  args.base = integer("base", base);
  args.height = integer("height", height);
  return Scene(frontend::reshapeCase(args));
}

}  // namespace
}  // namespace datomsim::python

PYBIND11_MODULE(_core, module) {
  using namespace datomsim;
  using namespace datomsim::python;
  module.doc() = "datomsim's C++ core: scenes, reach, moves, runs (see the package datomsim)";
  py::register_exception<frontend::UsageError>(module, "Error", PyExc_ValueError);
  py::register_exception<frontend::CheckFailed>(module, "CheckFailed", PyExc_RuntimeError);

  py::class_<Scene>(module, "Scene", "A scene: modules in an FCC lattice, and target shapes")
      .def("__len__", &Scene::size)
      .def_property_readonly("cells", &Scene::cells, "Module cells, (n, 3) int32, in file order")
      .def_property_readonly("ids", &Scene::ids, "Module ids, (n,) uint32")
      .def_property_readonly("colors", &Scene::colors, "Module colours, (n, 3) uint8 RGB")
      .def_property_readonly("orientations", &Scene::orientations,
                             "Orientation codes 0..23, (n,) uint8")
      .def_property_readonly("grid", &Scene::grid, "The grid size (x, y, z), or None")
      .def_property_readonly("name", &Scene::name)
      .def_property("module", &Scene::module, &Scene::setModule,
                    "What the modules are: \"datom\" or \"catom3d\" (saved with the scene)")
      .def_property_readonly("targets", &Scene::targets,
                             "The cells of each target shape, (k, 3) int32 each")
      .def("add", &Scene::add, py::arg("cell"), py::arg("orientation") = 0,
           py::arg("color") = std::tuple{128, 128, 128},
           "Add a module at a free cell inside the world; returns its id")
      .def("remove", &Scene::remove, py::arg("id"))
      .def("move", &Scene::move, py::arg("id"), py::arg("cell"),
           "Put a module at another cell (no motion rule is asked: the scene is edited)")
      .def("module_at", &Scene::moduleAt, py::arg("cell"), "The id of the module there, or None")
      .def("free_surface_cells", &Scene::freeSurfaceCells,
           "Empty cells inside the world next to a module, (m, 3), sorted")
      .def("save", &Scene::save, py::arg("path"),
           "Write a .json or VisibleSim .xml file (the XML with a grid VisibleSim can open)")
      .def("copy", &Scene::copy)
      .def("__repr__", &Scene::repr);

  module.def(
      "load_scene",
      [](const py::object& path) {
        const std::filesystem::path file = pathArgument({"load_scene()", "path"}, path);
        return Scene(frontend::unwrap(io::readScene(file)), file.string());
      },
      py::arg("path"), "Read a .json or VisibleSim .xml scene file");
  module.def("box", &box, py::arg("size"), py::arg("origin") = py::make_tuple(0, 0, 0),
             py::arg("upright") = false, "A box of modules (generate box)");
  module.def(
      "arch",
      [](const py::object& value) {
        const auto hole = int(integerArgument({"arch()", "hole"}, value, INT32_MIN, INT32_MAX));
        return sceneOf(frontend::unwrap(scene::paperArch(hole)),
                       fmt::format("paper arch, hole {} high", hole));
      },
      py::arg("hole") = 2, "The paper's scene with an arch whose hole is 2 or 1 high");
  module.def("random_scene", &randomScene, py::arg("count"), py::arg("seed") = 1,
             py::arg("grid") = py::none(), "A random connected scene (generate random)");
  module.def(
      "reshape", &reshape, py::arg("case"), py::arg("length") = 8,
      py::arg("floor") = py::make_tuple(12, 12), py::arg("modules") = 20, py::arg("seed") = 1,
      py::arg("side") = 96, py::arg("base") = 0, py::arg("height") = 2,
      "A reconfiguration case (generate reshape): its scene, the shape to build as its target");
  module.def("reach", &reach, py::arg("scene"), py::arg("goal"), py::arg("start") = py::none(),
             py::arg("rules") = "paper", py::arg("attachment") = true,
             py::arg("connectivity") = false, py::arg("module") = py::none(),
             py::arg("rolling") = "symmetric");
  module.def("moves_json", &moves, py::arg("scene"), py::arg("at"), py::arg("rules") = "paper",
             py::arg("attachment") = true, py::arg("module") = py::none(),
             py::arg("rolling") = "symmetric");
  module.def("run", &run, py::arg("scene"), py::arg("program"), py::arg("options"));
  module.def("loads_json", &loads, py::arg("scene"), py::arg("options"));
  module.def("geometry", &geometryOf, py::arg("radius") = 1.0, py::arg("thickness") = 0.0,
             py::arg("fraction") = py::none());
}
