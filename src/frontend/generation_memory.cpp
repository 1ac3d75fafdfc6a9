#include "frontend/generation_memory.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "common/available_memory.h"
#include "frontend/arguments.h"
#include "frontend/reshape_case.h"
#include "frontend/usage_error.h"
#include "world/world.h"

namespace datomsim::frontend {

namespace {
constexpr uint64_t kGeneratedBaseBytes = uint64_t{200} << 20;
}  // namespace

void refuseBeyondMemory(int64_t modules, const std::string& what, uint64_t bytesPerModule) {
  const std::optional<uint64_t> available = availableMemoryBytes();
  if (!available || modules <= 0 || modules > int64_t(world::kMaxModules)) return;
  const uint64_t needed = kGeneratedBaseBytes + uint64_t(modules) * bytesPerModule;
  if (needed > *available) {
    throw UsageError(
        fmt::format("{} {} modules, about {:.1f} GB to generate; this process may take {:.1f} GB "
                    "(the memory available, or ulimit -v)",
                    what, modules, double(needed) / 1e9, double(*available) / 1e9));
  }
}

int64_t reshapeModulesAbout(const ReshapeArguments& args) {
  const auto floorArea = [&]() -> int64_t {
    const geometry::Cell size = parseCell("--floor", args.floor + ",1");
    return int64_t{std::max(size.x, 0)} * std::max(size.y, 0);
  };
  // The edge of a pyramid's base or a cube: side / 8 unless given.
  const int64_t side = std::max(args.side, 0);
  const int64_t edge = args.base > 0 ? args.base : side / 8;
  if (args.kase == "line") return (int64_t{std::max(args.length, 0)} + 4) * 8 + args.length;
  if (args.kase == "heap") return floorArea() + floorArea() / 3;  // the cylinder on top
  if (args.kase == "random") return floorArea() + std::max(args.modules, 0);
  if (args.kase == "cube") return side * side + edge * edge * edge;
  if (args.kase == "pyramid") return side * side + edge * (edge + 1) * (2 * edge + 1) / 6;
  return 0;
}

}  // namespace datomsim::frontend
