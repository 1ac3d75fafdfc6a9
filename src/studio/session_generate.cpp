// The studio's `generate`: a scene made as `datomsim generate KIND` makes it, from the command
// line's options by their names (docs/studio.md, "Protocol").
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string_view>

#include "frontend/reshape_case.h"
#include "frontend/scene_generators.h"
#include "frontend/usage_error.h"
#include "studio/request_fields.h"
#include "studio/session.h"

namespace datomsim::studio {

using frontend::UsageError;
using Json = nlohmann::json;

namespace {

// Each generator's options, by the command line's names (without the dashes).
constexpr std::array<std::string_view, 4> kBoxKeys = {"size", "origin", "grid", "upright"};
constexpr std::array<std::string_view, 1> kArchKeys = {"hole"};
constexpr std::array<std::string_view, 5> kRandomKeys = {"seed", "count", "grid", "height",
                                                         "random-orientations"};
constexpr std::array<std::string_view, 8> kReshapeKeys = {"case", "floor",  "length", "modules",
                                                          "seed", "height", "side",   "base"};

// Refuses a field the generator does not take, naming those it does.
template <size_t N>
void onlyKnown(const Json& request, const std::string& kind,
               const std::array<std::string_view, N>& keys) {
  for (const auto& [key, value] : request.items()) {
    if (key == "op" || key == "kind" || std::find(keys.begin(), keys.end(), key) != keys.end()) {
      continue;
    }
    throw UsageError(fmt::format("unknown generate {} argument \"{}\": one of {}", kind, key,
                                 fmt::join(keys, ", ")));
  }
}

// An integer option that fits an int (the command line's): a larger one is refused, not cut.
int smallInteger(const Json& request, const char* key) {
  const int64_t value = integer(request, key);
  if (value < INT32_MIN || value > INT32_MAX) {
    throw UsageError(fmt::format("\"{}\" {} is out of range", key, value));
  }
  return int(value);
}

io::Scene worldScene(frontend::GeneratedWorld made) {
  io::Scene scene;
  scene.world = std::move(made.world);
  scene.name = std::move(made.name);
  return scene;
}

}  // namespace

Json Session::generate(const Json& request) {
  if (running()) throw UsageError("the scene cannot change during a run: stop it first");
  if (!request.contains("kind")) {
    throw UsageError("generate: \"kind\" is needed: box, arch, random or reshape");
  }
  const std::string& kind = text(request, "kind");
  io::Scene made;
  if (kind == "box") {
    onlyKnown(request, kind, kBoxKeys);
    if (!request.contains("size")) throw UsageError("generate box: \"size\" is needed (X,Y,Z)");
    frontend::BoxArguments args;
    args.size = text(request, "size");
    if (request.contains("origin")) args.origin = text(request, "origin");
    if (request.contains("grid")) args.grid = text(request, "grid");
    if (request.contains("upright")) args.upright = flag(request, "upright");
    made = worldScene(frontend::generateBox(args));
  } else if (kind == "arch") {
    onlyKnown(request, kind, kArchKeys);
    frontend::ArchArguments args;
    if (request.contains("hole")) args.hole = smallInteger(request, "hole");
    made = worldScene(frontend::generateArch(args));
  } else if (kind == "random") {
    onlyKnown(request, kind, kRandomKeys);
    frontend::RandomArguments args;
    if (request.contains("seed")) args.seed = seedOf(request);
    if (request.contains("count")) {
      const int64_t count = integer(request, "count");
      if (count < 1)
        throw UsageError(fmt::format("--count must be an integer >= 1, got {}", count));
      args.count = size_t(count);
    }
    if (request.contains("grid")) args.grid = text(request, "grid");
    if (request.contains("height")) args.height = smallInteger(request, "height");
    if (request.contains("random-orientations")) {
      args.orientations = flag(request, "random-orientations");
    }
    made = worldScene(frontend::generateRandom(args));
  } else if (kind == "reshape") {
    onlyKnown(request, kind, kReshapeKeys);
    if (!request.contains("case")) {
      throw UsageError(
          "generate reshape: \"case\" is needed: arch2, arch1, line, heap, random, pyramid or "
          "cube");
    }
    frontend::ReshapeArguments args;
    args.kase = text(request, "case");
    if (request.contains("floor")) args.floor = text(request, "floor");
    if (request.contains("seed")) args.seed = seedOf(request);
    for (auto [key, field] : {std::pair{"length", &args.length},
                              {"modules", &args.modules},
                              {"height", &args.height},
                              {"side", &args.side},
                              {"base", &args.base}}) {
      if (request.contains(key)) *field = smallInteger(request, key);
    }
    if (args.height < 1 || args.height > 64) {
      throw UsageError(fmt::format("--height: Value {} not in range [1 - 64]", args.height));
    }
    made = frontend::reshapeCase(args);
  } else {
    throw UsageError("generate: kind \"" + kind + "\" not in {box,arch,random,reshape}");
  }
  const std::string name = made.name.value_or("generated " + kind);
  replaceScene(std::move(made), name);
  Json reply;
  reply["modules"] = scene_.world.size();
  reply["targets"] = scene_.targets.size();
  return reply;
}

}  // namespace datomsim::studio
