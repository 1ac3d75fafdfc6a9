// A scene as the files carry it: a World plus what the file formats hold besides modules.
//
// Both formats (VisibleSim's XML and the project's JSON, docs/file-formats.md) read into and write
// from this one type, so converting between them is a read and a write. The grid size lives in the
// World's Bounds. What the files carry for VisibleSim's viewer (block size, camera, spotlight,
// window size) is kept verbatim so that XML -> JSON -> XML gives the same file back; the simulator
// itself never looks at it. Target shapes (VisibleSim's <targetList>) ride along for the algorithms
// that reconfigure the modules into them.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "target/target.h"
#include "world/module_kind.h"
#include "world/world.h"

namespace datomsim::io {

// One attribute of a VisibleSim XML element, kept as text.
struct Attribute {
  std::string name;
  std::string value;
  bool operator==(const Attribute&) const = default;
};

// Attributes in file order: writing them back in the same order keeps round trips byte-stable.
using AttributeList = std::vector<Attribute>;

// VisibleSim viewer settings read from (and written back to) the XML.
struct VisibleSimView {
  // Attributes of <world> other than gridSize, name and description (e.g. windowSize).
  AttributeList world;
  // The attributes of <camera> and <spotlight>, when the file has those elements.
  std::optional<AttributeList> camera;
  std::optional<AttributeList> spotlight;

  bool empty() const { return world.empty() && !camera && !spotlight; }
  bool operator==(const VisibleSimView&) const = default;
};

// VisibleSim's default block size (blockList blockSize="10,10,10").
inline constexpr std::array<double, 3> kDefaultBlockSize = {10, 10, 10};

struct Scene {
  // Modules in file order, with latches set between all neighbours once read.
  world::World world{};
  // What the modules are (JSON "module", XML <blockList moduleKind=...>; docs/file-formats.md).
  world::ModuleKind moduleKind = world::ModuleKind::kDatom;
  // Size of a module for VisibleSim's viewer, in its own units (the lattice spacing).
  std::array<double, 3> blockSize = kDefaultBlockSize;
  std::optional<std::string> name;
  std::optional<std::string> description;
  VisibleSimView visibleSim;
  // Target shapes in file order, kept as the file gives them (target/target.h).
  std::vector<target::Target> targets;
  // Module programs' parameters (JSON "parameters"), by program name, then parameter name, as
  // text (docs/file-formats.md); the program checks them when it runs.
  std::map<std::string, std::map<std::string, std::string>> parameters;
};

}  // namespace datomsim::io
