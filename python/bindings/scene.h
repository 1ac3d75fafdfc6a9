// The scene Python holds (datomsim.Scene) and the conversions between Python values and the
// command line's: cells given as tuples or text, arrays of cells, module kinds by name.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <fmt/format.h>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "arguments.h"
#include "frontend/output_file.h"
#include "frontend/usage_error.h"
#include "frontend/visiblesim_grid.h"
#include "geometry/cell.h"
#include "geometry/lattice.h"
#include "io/scene.h"
#include "io/scene_file.h"
#include "world/module_kind.h"
#include "world/world.h"

namespace datomsim::python {

namespace py = pybind11;
using geometry::Cell;

// An (n, 3) int32 array of cells.
py::array_t<int32_t> cellArray(const std::vector<Cell>& cells);

// The module kind named, or the scene's; refused as the command line refuses it.
world::ModuleKind kindOf(const std::optional<std::string>& module, world::ModuleKind scene);

// A module's colour: three integers 0..255.
Color colorArgument(const py::object& color);

// A module's id: an integer 0 .. 2^32 - 1.
ModuleId idArgument(const std::string& function, const py::object& id);

// A scene in memory: the modules and what the file formats carry besides them.
class Scene {
 public:
  explicit Scene(io::Scene scene, std::string source = {})
      : scene_(std::move(scene)), source_(std::move(source)) {}

  const io::Scene& scene() const { return scene_; }
  // The file the scene was read from, or empty: outputs never overwrite it.
  const std::string& source() const { return source_; }
  std::string module() const { return std::string(world::toString(scene_.moduleKind)); }
  void setModule(const py::object& module) {
    scene_.moduleKind = kindOf(stringArgument({"Scene", "module"}, module), scene_.moduleKind);
  }

  size_t size() const { return scene_.world.size(); }

  py::array_t<int32_t> cells() const {
    std::vector<Cell> cells;
    cells.reserve(size());
    for (const world::Module& m : scene_.world.modules()) cells.push_back(m.cell);
    return cellArray(cells);
  }
  py::array_t<uint32_t> ids() const {
    py::array_t<uint32_t> out{py::ssize_t(size())};
    auto view = out.mutable_unchecked<1>();
    py::ssize_t k = 0;
    for (const world::Module& m : scene_.world.modules()) view(k++) = m.id.value;
    return out;
  }
  py::array_t<uint8_t> colors() const {
    py::array_t<uint8_t> out({py::ssize_t(size()), py::ssize_t(3)});
    auto view = out.mutable_unchecked<2>();
    py::ssize_t k = 0;
    for (const world::Module& m : scene_.world.modules()) {
      view(k, 0) = m.color.r;
      view(k, 1) = m.color.g;
      view(k, 2) = m.color.b;
      ++k;
    }
    return out;
  }
  py::array_t<uint8_t> orientations() const {
    py::array_t<uint8_t> out{py::ssize_t(size())};
    auto view = out.mutable_unchecked<1>();
    py::ssize_t k = 0;
    for (const world::Module& m : scene_.world.modules()) {
      view(k++) = uint8_t(m.orientation.code());
    }
    return out;
  }
  std::optional<std::tuple<int, int, int>> grid() const {
    const auto& size = scene_.world.bounds().gridSize;
    if (!size) return std::nullopt;
    return std::tuple{size->x, size->y, size->z};
  }
  std::optional<std::string> name() const { return scene_.name; }

  // Adds a module (the next free id) and latches it to its neighbours; returns its id.
  uint32_t add(const py::object& cell, const py::object& orientation, const py::object& color) {
    const Cell at = cellArgument({"add()", "cell"}, cell, "cell");
    const auto number =
        integerArgument({"add()", "orientation"}, orientation, INT32_MIN, INT32_MAX);
    const auto code = geometry::Orientation::fromCode(int(number));
    if (!code) throw frontend::UsageError(fmt::format("orientation {}: a code in 0..23", number));
    const Color rgb = colorArgument(color);
    const ModuleId id = scene_.world.nextFreeId();
    frontend::check(scene_.world.add({id, at, *code, rgb}));
    scene_.world.latchAllNeighbours();
    return id.value;
  }
  void remove(const py::object& id) {
    frontend::check(scene_.world.remove(idArgument("remove()", id)));
  }
  void move(const py::object& id, const py::object& cell) {
    frontend::check(scene_.world.move(idArgument("move()", id),
                                      cellArgument({"move()", "cell"}, cell, "cell")));
    scene_.world.latchAllNeighbours();
  }
  std::optional<uint32_t> moduleAt(const py::object& cell) const {
    const world::Module* m =
        scene_.world.moduleAt(cellArgument({"module_at()", "cell"}, cell, "cell"));
    if (m == nullptr) return std::nullopt;
    return m->id.value;
  }

  // Every empty cell inside the world next to a module, sorted by x, then y, then z: where a
  // module could be added or a mobile could stand.
  py::array_t<int32_t> freeSurfaceCells() const {
    std::set<std::tuple<int32_t, int32_t, int32_t>> found;
    for (const world::Module& m : scene_.world.modules()) {
      for (int d = 0; d < geometry::kDirectionCount; ++d) {
        const Cell next = m.cell + geometry::neighbourOffset(d);
        if (scene_.world.isInside(next) && scene_.world.moduleAt(next) == nullptr) {
          found.insert({next.x, next.y, next.z});
        }
      }
    }
    std::vector<Cell> cells;
    cells.reserve(found.size());
    for (const auto& [x, y, z] : found) cells.push_back({x, y, z});
    return cellArray(cells);
  }

  // The cells of each target shape, in the scene's order.
  std::vector<py::array_t<int32_t>> targets() const {
    std::vector<py::array_t<int32_t>> out;
    for (const target::Target& shape : scene_.targets) {
      out.push_back(cellArray(frontend::unwrap(shape.cells())));
    }
    return out;
  }

  void save(const py::object& where) const {
    const std::filesystem::path path = pathArgument({"save()", "path"}, where);
    frontend::unwrap(io::sceneFormatOf(path));
    // Opened as the commands open their outputs (a device written into, a FIFO with no reader
    // refused); the scene's own file may be saved over.
    frontend::CommandFiles files({}, {{"path", path.string()}});
    io::Scene written = scene_;
    const frontend::Reporter quiet(/*quiet=*/true);
    // Python says nothing on standard error: the grid is in the file, for Python to read.
    frontend::declareGridForVisibleSim(written, path.string(), quiet);
    files.write("path", [&](std::FILE* file) { return io::writeScene(written, path, file); });
    files.commit(quiet);
  }

  Scene copy() const { return *this; }

  std::string repr() const {
    return fmt::format(
        "<datomsim.Scene {}{} modules{}>", scene_.name ? *scene_.name + ": " : "", size(),
        scene_.targets.empty() ? "" : fmt::format(", {} target(s)", scene_.targets.size()));
  }

 private:
  io::Scene scene_;
  std::string source_;
};

// A generated scene: its modules latched to their neighbours, and its name.
Scene sceneOf(world::World world, std::string name);

// A datomsim.Scene, or a TypeError naming the argument.
const Scene& sceneArgument(const Argument& argument, const py::object& value);
// The file a scene was read from, when it was: no output may overwrite it.
std::vector<frontend::NamedPath> inputsOf(const Scene& scene);

}  // namespace datomsim::python
