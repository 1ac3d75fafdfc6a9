#include "scene.h"

#include <fmt/format.h>

#include <utility>

#include "frontend/arguments.h"

namespace datomsim::python {

using frontend::UsageError;

Color colorArgument(const py::object& color) {
  const auto refuse = [&] {
    return py::type_error(fmt::format(
        "add(): color must be three integers 0..255 (r, g, b), got {}", typeName(color)));
  };
  if (PyUnicode_Check(color.ptr()) || !PySequence_Check(color.ptr()) ||
      PySequence_Size(color.ptr()) != 3) {
    PyErr_Clear();
    throw refuse();
  }
  const py::sequence channels = py::reinterpret_borrow<py::sequence>(color);
  int64_t rgb[3] = {};
  for (size_t k = 0; k < 3; ++k) {
    const py::object channel = channels[k];
    if (!PyIndex_Check(channel.ptr()) || PyBool_Check(channel.ptr())) throw refuse();
    rgb[k] = integerArgument({"add()", "color"}, channel, INT64_MIN, INT64_MAX);
  }
  for (const int64_t channel : rgb) {
    if (channel < 0 || channel > 255) {
      throw UsageError(fmt::format("color ({},{},{}): channels in 0..255", rgb[0], rgb[1], rgb[2]));
    }
  }
  return Color{uint8_t(rgb[0]), uint8_t(rgb[1]), uint8_t(rgb[2])};
}

ModuleId idArgument(const std::string& function, const py::object& id) {
  return ModuleId{uint32_t(integerArgument({function, "id"}, id, 0, UINT32_MAX))};
}

py::array_t<int32_t> cellArray(const std::vector<Cell>& cells) {
  py::array_t<int32_t> out({py::ssize_t(cells.size()), py::ssize_t(3)});
  auto view = out.mutable_unchecked<2>();
  for (size_t k = 0; k < cells.size(); ++k) {
    view(py::ssize_t(k), 0) = cells[k].x;
    view(py::ssize_t(k), 1) = cells[k].y;
    view(py::ssize_t(k), 2) = cells[k].z;
  }
  return out;
}

world::ModuleKind kindOf(const std::optional<std::string>& module, world::ModuleKind scene) {
  if (!module) return scene;
  if (const auto kind = world::moduleKindNamed(*module)) return *kind;
  throw frontend::UsageError("--module: " + *module + " not in {datom,catom3d}");
}

Scene sceneOf(world::World world, std::string name) {
  world.latchAllNeighbours();
  io::Scene scene;
  scene.world = std::move(world);
  scene.name = std::move(name);
  return Scene(std::move(scene));
}

const Scene& sceneArgument(const Argument& argument, const py::object& value) {
  if (!py::isinstance<Scene>(value)) {
    throw py::type_error(
        fmt::format("{} must be a datomsim.Scene, got {}", argument.named(), typeName(value)));
  }
  return value.cast<const Scene&>();
}

// The file a scene was read from, when it was: no output may overwrite it.
std::vector<frontend::NamedPath> inputsOf(const Scene& scene) {
  if (scene.source().empty()) return {};
  return {{"scene", scene.source()}};
}

}  // namespace datomsim::python
