// Which module a world is made of. Every module of a world is of the same kind: the Datom of the
// paper (it turns about a pivot, deforming its neighbours, docs/datom-model.md) or the 3D Catom it
// grew from (it rolls on its neighbours' borders, docs/catom3d.md). Both live on the same FCC
// lattice and the same world; only the motions differ.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace datomsim::world {

enum class ModuleKind : uint8_t { kDatom, kCatom3D };

// The names the command line (--module) and the scene files use.
inline constexpr std::array<std::string_view, 2> kModuleKindNames = {"datom", "catom3d"};

constexpr std::string_view toString(ModuleKind kind) {
  return kModuleKindNames[static_cast<size_t>(kind)];
}

constexpr std::optional<ModuleKind> moduleKindNamed(std::string_view name) {
  if (name == kModuleKindNames[0]) return ModuleKind::kDatom;
  if (name == kModuleKindNames[1]) return ModuleKind::kCatom3D;
  return std::nullopt;
}

}  // namespace datomsim::world
