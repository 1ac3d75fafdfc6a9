// A target shape for self-reconfiguration, as VisibleSim's scene files describe it in
// <targetList> (docs/file-formats.md, "Targets"): either a list of cells (format "grid") or a CSG
// shape placed in the lattice (format "csg").
//
// A Target is a value that keeps what the file says verbatim, so that writing it back loses
// nothing: a grid's cells with their optional colours in file order; a CSG's text, byte for byte,
// and which of its placement attributes the file gave. Membership is exact and cheap for both
// formats; listing a CSG target's cells scans the cells whose centres lie in the shape's bounding
// box, and refuses a box that is unbounded or holds more than kMaxListedCells cells.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "datomsim/result.h"
#include "datomsim/values.h"
#include "geometry/cell.h"
#include "geometry/vec3.h"
#include "target/csg.h"
#include "world/world.h"

namespace datomsim::target {

enum class Format { kGrid, kCsg };

// "grid" or "csg", as the files write it.
std::string_view formatName(Format format);

// The most cells a target may list (its CSG box, or a box given on the command line): a scan of
// 45 million candidates takes 0.7 s (a cube) to 1.5 s (a cube less a cone and a sphere) on the
// development machine, and their list up to 800 MB while it grows.
inline constexpr size_t kMaxListedCells = 50'000'000;

// The most containment tests a CSG target's scan may make: its candidate cells times the nodes
// of its shape (each candidate may visit every node). A cube of 16 million candidates less 50
// spheres (8e8 tests) takes 3.9 s on the development machine; a shape of many nodes over a wide
// box would run for minutes.
inline constexpr double kMaxCsgTests = 1e9;

// One cell of a grid target; the colour is there when the file gives one.
struct GridCell {
  geometry::Cell cell;
  std::optional<Color> color;
  bool operator==(const GridCell&) const = default;
};

// Where a CSG shape sits in the lattice: the attributes of VisibleSim's <csg> element. Each is
// kept only when the file gives it; the ...OrDefault functions give VisibleSim's defaults.
struct CsgPlacement {
  // Move the shape by minus its bounding box's low corner, so that the corner sits at the lattice
  // origin (VisibleSim's default).
  std::optional<bool> boundingBox;
  // Move it by (1,1,1) more.
  std::optional<bool> offset;
  // Move it by this vector, in lattice spacings.
  std::optional<geometry::Vec3> translate;

  bool boundingBoxOrDefault() const { return boundingBox.value_or(true); }
  bool offsetOrDefault() const { return offset.value_or(false); }
  geometry::Vec3 translateOrDefault() const { return translate.value_or(geometry::Vec3{}); }
  bool operator==(const CsgPlacement&) const = default;
};

class Target {
 public:
  // A grid target of cells in order. `color` is the <target> element's colour (VisibleSim's
  // default for cells without one). Refuses a cell listed twice, naming both places.
  static Result<Target> grid(std::vector<GridCell> cells, std::optional<Color> color = {});
  // The same for plain cells, without colours.
  static Result<Target> grid(std::span<const geometry::Cell> cells);

  // A CSG target; refuses a text that does not parse, with the parser's error (csg_parser.h).
  // `color` is the <target> element's colour: VisibleSim ignores it here, the files keep it.
  static Result<Target> csg(std::string content, CsgPlacement placement = {},
                            std::optional<Color> color = {});

  Format format() const { return format_; }
  // The colour attribute of the <target> element, when the file gives one.
  const std::optional<Color>& color() const { return color_; }

  // Grid targets: the cells in file order (empty for CSG targets).
  const std::vector<GridCell>& gridCells() const { return gridCells_; }

  // CSG targets: the text as the file gives it, the placement attributes, and the parsed shape.
  const std::string& csgContent() const { return csgContent_; }
  const CsgPlacement& csgPlacement() const { return csgPlacement_; }
  const csg::Node& csgShape() const { return csgShape_; }

  // Where a cell's centre lands in the shape's own coordinates (VisibleSim's
  // TargetCSG::gridToCSGPosition): worldPosition(cell, 1), plus the shape's bounding box's low
  // corner when boundingBox is true, minus translate, minus (1,1,1) when offset is true.
  geometry::Vec3 csgPoint(const geometry::Cell& cell) const;

  // Whether the target covers a cell: listed (grid), or its centre inside the shape (csg).
  bool contains(const geometry::Cell& cell) const;

  // Every cell the target covers: grid, in file order; csg, x fastest, then y, then z. Refuses a
  // CSG target whose box is unbounded or holds more than kMaxListedCells cells.
  Result<std::vector<geometry::Cell>> cells() const;

  // The number of cells(), with the same refusals, counted without holding the list.
  Result<size_t> count() const;

  // The first of the target's cells that no module may hold in any world (below the ground, or
  // beyond the coordinate range), in the order of cells(), or nullopt. A grid, which may clip a
  // shape at its edges as VisibleSim's own examples do, is not asked. A CSG target is scanned only
  // where its candidate cells leave those bounds (its margin layer under the ground, say), so
  // that checking costs little more than the box's rows; one that cells() would refuse is not
  // looked at (listing it refuses it).
  std::optional<geometry::Cell> firstCellNoModuleMayHold() const;

  // How many of the target's cells hold a module of the world. Never refuses: it asks each
  // module's cell, not each of the target's cells.
  size_t filledIn(const world::World& world) const;

  // Same format, colour and cells (grid) or text and placement (csg), as the files would write.
  bool operator==(const Target& other) const;

 private:
  Target() = default;

  // Calls `visit` for each cell of a CSG target, in the order of cells(), after the refusals.
  Status scanCsgCells(const std::function<void(const geometry::Cell&)>& visit) const;

  // The candidate cells of a CSG target: layers zLow..zHigh, and in each the columns and rows
  // whose centres may lie in [low, high] (lattice frame). Refused as cells() refuses.
  struct CandidateBox {
    int64_t zLow, zHigh;
    geometry::Vec3 low, high;
  };
  Result<CandidateBox> csgCandidates() const;

  Format format_ = Format::kGrid;
  std::optional<Color> color_;
  std::vector<GridCell> gridCells_;
  // The grid's cells sorted, for membership by binary search.
  std::vector<geometry::Cell> sortedCells_;
  std::string csgContent_;
  CsgPlacement csgPlacement_;
  csg::Node csgShape_;
  // csgPoint(cell) - worldPosition(cell, 1), fixed by the shape and its placement.
  geometry::Vec3 csgShift_;
};

}  // namespace datomsim::target
