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
#include "run.h"
#include "scene.h"
#include "scene/box.h"
#include "scene/paper_arch.h"
#include "scene/random_scene.h"

namespace py = pybind11;

namespace datomsim::python {
namespace {

using frontend::UsageError;
using geometry::Cell;

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
