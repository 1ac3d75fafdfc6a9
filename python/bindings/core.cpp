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

frontend::RuleArguments ruleArguments(const std::string& rules, bool attachment,
                                      bool connectivity) {
  frontend::RuleArguments arguments;
  arguments.rules = rules;
  arguments.attachment = onOff(attachment);
  arguments.connectivity = onOff(connectivity);
  return arguments;
}

catom3d::RollRules rollingOf(const std::string& rolling) {
  if (const auto rules = catom3d::rollRulesNamed(rolling)) return *rules;
  throw frontend::UsageError("--rolling: " + rolling + " not in {symmetric,visiblesim}");
}

// {"cells": (n, 3), "distances": (n,), "path": (p, 3), "goal": (3,)}: `reach --out` as arrays.
py::dict reach(const Scene& scene, const py::object& goal, const py::object& start,
               const std::string& rules, bool attachment, bool connectivity,
               const std::optional<std::string>& module, const std::string& rolling) {
  const Cell at = cellArgument(goal, "--goal");
  const frontend::MotionChoice model{kindOf(module, scene.scene().moduleKind),
                                     ruleArguments(rules, attachment, connectivity).options(),
                                     rollingOf(rolling)};
  const frontend::ReachOutput reached =
      frontend::reachOnScene(scene.scene(), at, optionalCell(start, "--start"), model);
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
std::string moves(const Scene& scene, const py::object& at, const std::string& rules,
                  bool attachment, const std::optional<std::string>& module,
                  const std::string& rolling) {
  const Cell cell = cellArgument(at, "--at");
  const world::World& world = scene.scene().world;
  if (!world.isInside(cell)) {
    throw UsageError("--at " + geometry::toString(cell) + " " + world.bounds().whyOutside(cell));
  }
  const world::Module* mobile = world.moduleAt(cell);
  const motion::Mobile where{cell, mobile ? std::optional(mobile->id) : std::nullopt};
  const frontend::MotionChoice model{kindOf(module, scene.scene().moduleKind),
                                     ruleArguments(rules, attachment, false).options(),
                                     rollingOf(rolling)};
  if (model.kind == world::ModuleKind::kCatom3D) {
    const catom3d::RollTable rolls;
    return frontend::rollsJson(cell, catom3d::evaluateAll(world, rolls, where, model.rolling),
                               model);
  }
  const motion::RuleTable table;
  return frontend::movesJson(cell, motion::evaluateAll(world, table, where, model.datom));
}

// A number of loads(), or the error naming it and what it got.
double numberArgument(const py::handle& value, const std::string& name) {
  if (py::isinstance<py::bool_>(value) ||
      !(py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value))) {
    throw py::type_error(
        fmt::format("loads(): {} must be a number, got {}", name,
                    py::str(py::type::of(value).attr("__name__")).cast<std::string>()));
  }
  return value.cast<double>();
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

// The JSON text of `loads --out`; the pictures asked for written as the command writes them.
std::string loads(const Scene& scene, const py::dict& options) {
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
      *number->second = numberArgument(value, name);
    } else if (name == "gravity") {
      const auto parts = value.cast<py::sequence>();
      if (py::isinstance<py::str>(value) || parts.size() != 3) {
        throw py::type_error("loads(): gravity must be three numbers (x, y, z), m/s^2");
      }
      // Checked as the command line checks --gravity, with its message.
      p.gravity = frontend::parseVector(
          "--gravity",
          fmt::format("{},{},{}", numberArgument(parts[0], "gravity"),
                      numberArgument(parts[1], "gravity"), numberArgument(parts[2], "gravity")));
    } else if (name == "top") {
      if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value)) {
        throw py::type_error("loads(): top must be an integer");
      }
      args.top = value.cast<int>();
    } else if (name == "view" || name == "solver" || name == "png" || name == "svg" ||
               name == "name") {
      if (!py::isinstance<py::str>(value)) {
        throw py::type_error(fmt::format("loads(): {} must be a string", name));
      }
      const std::string text = value.cast<std::string>();
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

// (the JSON text of `run --out`, the trace or None, the failure or None).
std::tuple<std::string, std::optional<std::string>, std::optional<std::string>> run(
    const Scene& scene, const std::string& program, const py::dict& options) {
  frontend::RunArguments args;
  args.program = program;
  std::optional<std::string> tracePath;
  const std::set<std::string> known = {
      "goal",      "start",       "rules",  "attachment", "connectivity", "seed",       "delay_ms",
      "jitter_ms", "max_motions", "target", "timeout",    "until",        "params",     "root",
      "trace",     "scene_name",  "module", "rolling",    "gravity",      "load_region"};
  const std::vector<std::pair<std::string, double*>> loadNumbers =
      loadParameterKeywords(args.loads);
  for (const auto& [key, value] : options) {
    const std::string name = key.cast<std::string>();
    const auto loadNumber = std::find_if(loadNumbers.begin(), loadNumbers.end(),
                                         [&](const auto& entry) { return entry.first == name; });
    if (!known.contains(name) && loadNumber == loadNumbers.end()) {
      throw UsageError(
          fmt::format("run: unknown option {} (known: goal, start, rules, "
                      "attachment, connectivity, seed, delay_ms, jitter_ms, "
                      "max_motions, target, timeout, until, params, root, trace, module, "
                      "rolling, gravity, load_region, radius, thickness, density, "
                      "solid_fraction, young_modulus, poisson_ratio, latch_force, latch_moment)",
                      name));
    }
    if (value.is_none()) continue;
    // The load model's, named as the command line's options for the shared refusals.
    if (loadNumber != loadNumbers.end()) {
      *loadNumber->second = numberArgument(value, name);
      std::string option = "--" + name;
      std::replace(option.begin(), option.end(), '_', '-');
      args.loadOptionsGiven.push_back(option);
      continue;
    }
    if (name == "gravity") {
      // True or "on", False or "off", or three numbers.
      if (py::isinstance<py::bool_>(value)) {
        args.gravity = value.cast<bool>() ? "on" : "off";
      } else if (py::isinstance<py::str>(value)) {
        args.gravity = value.cast<std::string>();
      } else {
        const auto parts = value.cast<py::sequence>();
        if (parts.size() != 3) {
          throw py::type_error(
              "run(): gravity must be True, False, \"on\", \"off\" or three "
              "numbers (x, y, z), m/s^2");
        }
        args.gravity =
            fmt::format("{},{},{}", numberArgument(parts[0], "gravity"),
                        numberArgument(parts[1], "gravity"), numberArgument(parts[2], "gravity"));
      }
      continue;
    }
    if (name == "load_region") {
      if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value)) {
        throw py::type_error("run(): load_region must be an integer");
      }
      args.loadRegion = value.cast<int>();
      args.loadOptionsGiven.push_back("--load-region");
      continue;
    }
    const auto cellText = [&](const char* option) {
      const Cell cell = cellArgument(value, option);
      return fmt::format("{},{},{}", cell.x, cell.y, cell.z);
    };
    if (name == "goal") args.goal = cellText("--goal");
    if (name == "start") args.start = cellText("--start");
    if (name == "root") args.root = cellText("--root");
    if (name == "rules") args.rules.rules = value.cast<std::string>();
    if (name == "attachment") args.rules.attachment = onOff(value.cast<bool>());
    if (name == "connectivity") {
      args.rules.connectivity = onOff(value.cast<bool>());
      args.connectivityGiven = true;
    }
    if (name == "seed") args.seed = py::str(value).cast<std::string>();
    if (name == "delay_ms") args.delayMs = value.cast<double>();
    if (name == "jitter_ms") args.jitterMs = value.cast<double>();
    if (name == "max_motions") args.maxMotions = value.cast<int>();
    if (name == "target") args.target = py::str(value).cast<std::string>();
    if (name == "timeout") args.timeoutS = value.cast<double>();
    if (name == "until") args.untilS = value.cast<double>();
    if (name == "trace") {
      // True: the trace's text returned; a path: the file to write it to.
      if (py::isinstance<py::str>(value)) {
        tracePath = value.cast<std::string>();
        if (tracePath->empty()) throw UsageError("run: trace is an empty file name");
      }
      args.wantTrace = tracePath || value.cast<bool>();
    }
    if (name == "module") args.module = value.cast<std::string>();
    if (name == "rolling") args.rolling = value.cast<std::string>();
    if (name == "params") {
      for (const auto& [k, v] : value.cast<py::dict>()) {
        args.parameters.push_back(py::str(k).cast<std::string>() + "=" +
                                  py::str(v).cast<std::string>());
      }
    }
  }
  const std::string sceneName = options.contains("scene_name")
                                    ? options["scene_name"].cast<std::string>()
                                    : scene.scene().name.value_or("a scene from Python");
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
std::string geometryOf(double radius, double thickness, const std::optional<double>& fraction) {
  if (fraction && !(*fraction >= 0 && *fraction <= 1)) {
    throw UsageError(fmt::format("--fraction: Value {} not in range [0 - 1]", *fraction));
  }
  return frontend::geometryJson(radius, thickness, fraction).dump();
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
      [](const std::filesystem::path& path) {
        return Scene(frontend::unwrap(io::readScene(path)), path.string());
      },
      py::arg("path"), "Read a .json or VisibleSim .xml scene file");
  module.def(
      "box",
      [](const py::object& size, const py::object& origin, bool upright) {
        scene::BoxOptions options;
        options.origin = cellArgument(origin, "--origin");
        options.upright = upright;
        const geometry::Cell cells = cellArgument(size, "--size");
        return sceneOf(frontend::unwrap(scene::box(cells, options)),
                       fmt::format("box {}x{}x{}", cells.x, cells.y, cells.z));
      },
      py::arg("size"), py::arg("origin") = py::make_tuple(0, 0, 0), py::arg("upright") = false,
      "A box of modules (generate box)");
  module.def(
      "arch",
      [](int hole) {
        return sceneOf(frontend::unwrap(scene::paperArch(hole)),
                       fmt::format("paper arch, hole {} high", hole));
      },
      py::arg("hole") = 2, "The paper's scene with an arch whose hole is 2 or 1 high");
  module.def(
      "random_scene",
      [](size_t count, uint64_t seed, const py::object& grid) {
        scene::RandomOptions options;
        options.gridSize = optionalCell(grid, "--grid");
        return sceneOf(frontend::unwrap(scene::random(seed, count, options)),
                       fmt::format("random, {} modules, seed {}", count, seed));
      },
      py::arg("count"), py::arg("seed") = 1, py::arg("grid") = py::none(),
      "A random connected scene (generate random)");
  module.def(
      "reshape",
      [](const std::string& kase, int length, const py::object& floor, int modules, uint64_t seed,
         int side, int base, int height) {
        frontend::ReshapeArguments args;
        args.kase = kase;
        args.length = length;
        const geometry::Cell size = cellArgument(
            py::isinstance<py::str>(floor)
                ? floor
                : py::object(py::make_tuple(floor[py::int_(0)], floor[py::int_(1)], 1)),
            "--floor");
        args.floor = fmt::format("{},{}", size.x, size.y);
        args.modules = modules;
        args.seed = std::to_string(seed);
        args.side = side;
        args.base = base;
        args.height = height;
        return Scene(frontend::reshapeCase(args));
      },
      py::arg("case"), py::arg("length") = 8, py::arg("floor") = py::make_tuple(12, 12),
      py::arg("modules") = 20, py::arg("seed") = 1, py::arg("side") = 96, py::arg("base") = 0,
      py::arg("height") = 2,
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
