#include "scene.h"

#include <fmt/format.h>

#include <utility>

#include "frontend/arguments.h"

namespace datomsim::python {

using frontend::UsageError;

Cell cellArgument(const py::handle& value, const std::string& option) {
  if (py::isinstance<py::str>(value)) return frontend::parseCell(option, value.cast<std::string>());
  if (py::isinstance<py::sequence>(value) && py::len(value) == 3) {
    const py::sequence items = value.cast<py::sequence>();
    std::string text;
    for (size_t k = 0; k < 3; ++k) {
      const py::handle item = items[k];
      if (!py::isinstance<py::int_>(item) && !(py::hasattr(item, "__index__"))) {
        throw UsageError(fmt::format("{} {}: expected three integers x,y,z", option,
                                     py::repr(value).cast<std::string>()));
      }
      text += (k ? "," : "") +
              py::str(py::int_(py::reinterpret_borrow<py::object>(item))).cast<std::string>();
    }
    return frontend::parseCell(option, text);
  }
  throw UsageError(fmt::format("{} {}: expected three integers x,y,z", option,
                               py::repr(value).cast<std::string>()));
}

std::optional<Cell> optionalCell(const py::object& value, const std::string& option) {
  if (value.is_none()) return std::nullopt;
  return cellArgument(value, option);
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

}  // namespace datomsim::python
