// `generate`, `convert` and `info`: making, translating and describing scene files.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "geometry/lattice.h"
#include "io/scene_file.h"
#include "scene/box.h"
#include "scene/paper_arch.h"
#include "scene/random_scene.h"

namespace datomsim::app {
namespace {

// The subcommands of `generate` share the output option.
CLI::App* addGenerator(CLI::App& generate, const std::string& name, const std::string& help,
                       std::string& out) {
  CLI::App* command = generate.add_subcommand(name, help);
  command->add_option("-o,--out", out, "Scene file to write (.xml or .json)")->required();
  return command;
}

void writeGenerated(world::World world, const std::string& name, const std::string& out) {
  io::Scene scene;
  scene.world = std::move(world);
  scene.name = name;
  check(io::writeScene(scene, out));
  fmt::print(stderr, "wrote {} ({} modules)\n", out, scene.world.size());
}

void addGenerate(CLI::App& app) {
  CLI::App* generate = app.add_subcommand("generate", "Make a scene: box, arch or random");
  generate->require_subcommand(1);

  struct BoxArguments {
    std::string size, origin = "0,0,0", grid, out;
  };
  auto box = std::make_shared<BoxArguments>();
  CLI::App* boxCommand = addGenerator(*generate, "box", "A box of modules", box->out);
  boxCommand->add_option("--size", box->size, "Size X,Y,Z in cells")->required();
  boxCommand->add_option("--origin", box->origin, "Corner cell x,y,z")->capture_default_str();
  boxCommand->add_option("--grid", box->grid, "Declare a grid X,Y,Z (default: none)");
  boxCommand->callback([box] {
    scene::BoxOptions options;
    options.origin = parseCell("--origin", box->origin);
    if (!box->grid.empty()) options.gridSize = parseCell("--grid", box->grid);
    const geometry::Cell size = parseCell("--size", box->size);
    writeGenerated(unwrap(scene::box(size, options)), "box " + box->size, box->out);
  });

  struct ArchArguments {
    int hole = 2;
    std::string out;
  };
  auto arch = std::make_shared<ArchArguments>();
  CLI::App* archCommand =
      addGenerator(*generate, "arch",
                   "The paper's experiment: a 7x7x2 box under an arch (section VII)", arch->out);
  archCommand->add_option("--hole", arch->hole, "Height of the arch's hole: 2 or 1")
      ->check(CLI::IsMember({1, 2}))
      ->capture_default_str();
  archCommand->callback([arch] {
    writeGenerated(unwrap(scene::paperArch(arch->hole)),
                   fmt::format("paper arch, hole {} high", arch->hole), arch->out);
  });

  struct RandomArguments {
    uint64_t seed = 1;
    size_t count = 100;
    std::string grid;
    int height = 3;
    bool orientations = false;
    std::string out;
  };
  auto random = std::make_shared<RandomArguments>();
  CLI::App* randomCommand = addGenerator(
      *generate, "random", "A random connected scene grown on the ground from a seed", random->out);
  randomCommand->add_option("--seed", random->seed, "Seed")->capture_default_str();
  randomCommand->add_option("--count", random->count, "Number of modules")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  randomCommand->add_option("--grid", random->grid, "Declare a grid X,Y,Z (default: none)");
  randomCommand->add_option("--height", random->height, "Layers the scene may use")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  randomCommand->add_flag("--random-orientations", random->orientations,
                          "Draw each module's orientation");
  randomCommand->callback([random] {
    scene::RandomOptions options;
    if (!random->grid.empty()) options.gridSize = parseCell("--grid", random->grid);
    options.maxHeight = random->height;
    options.randomOrientations = random->orientations;
    writeGenerated(unwrap(scene::random(random->seed, random->count, options)),
                   fmt::format("random, seed {}", random->seed), random->out);
  });
}

void addConvert(CLI::App& app) {
  struct Arguments {
    std::string in, out;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command =
      app.add_subcommand("convert", "Convert a scene between VisibleSim XML and JSON");
  command->add_option("scene", args->in, "Scene file to read (.xml or .json)")->required();
  command->add_option("-o,--out", args->out, "Scene file to write (.xml or .json)")->required();
  command->callback([args] {
    const io::Scene scene = unwrap(io::readScene(args->in));
    check(io::writeScene(scene, args->out));
  });
}

// Connected components of the modules, neighbours being the 12 lattice neighbours.
size_t countComponents(const world::World& world) {
  std::vector<bool> seen(world.size(), false);
  std::vector<uint32_t> stack;
  size_t components = 0;
  for (uint32_t start = 0; start < world.size(); ++start) {
    if (seen[start]) continue;
    ++components;
    seen[start] = true;
    stack.push_back(start);
    while (!stack.empty()) {
      const world::Module& module = world.modules()[stack.back()];
      stack.pop_back();
      for (int d = 0; d < geometry::kDirectionCount; ++d) {
        const world::Module* next = world.neighbour(module, d);
        if (!next) continue;
        const uint32_t index = *world.indexOf(next->id);
        if (!seen[index]) {
          seen[index] = true;
          stack.push_back(index);
        }
      }
    }
  }
  return components;
}

void addInfo(CLI::App& app) {
  struct Arguments {
    std::string scene;
    bool json = false;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command =
      app.add_subcommand("info", "Module count, bounds and connected components of a scene");
  command->add_option("scene", args->scene, "Scene file (.xml or .json)")->required();
  command->add_flag("--json", args->json, "Print one JSON object");
  command->callback([args] {
    const io::Scene scene = unwrap(io::readScene(args->scene));
    const world::World& world = scene.world;
    geometry::Cell low{INT32_MAX, INT32_MAX, INT32_MAX}, high{INT32_MIN, INT32_MIN, INT32_MIN};
    for (const world::Module& m : world.modules()) {
      low = {std::min(low.x, m.cell.x), std::min(low.y, m.cell.y), std::min(low.z, m.cell.z)};
      high = {std::max(high.x, m.cell.x), std::max(high.y, m.cell.y), std::max(high.z, m.cell.z)};
    }
    const size_t components = countComponents(world);
    nlohmann::ordered_json out;
    out["scene"] = args->scene;
    out["modules"] = world.size();
    out["components"] = components;
    if (world.size() > 0) {
      out["min_cell"] = {low.x, low.y, low.z};
      out["max_cell"] = {high.x, high.y, high.z};
    } else {
      out["min_cell"] = nullptr;
      out["max_cell"] = nullptr;
    }
    const auto& grid = world.bounds().gridSize;
    out["grid"] =
        grid ? nlohmann::ordered_json{grid->x, grid->y, grid->z} : nlohmann::ordered_json();
    if (args->json) {
      fmt::print("{}\n", out.dump());
      return;
    }
    fmt::print("scene       {}\nmodules     {}\ncomponents  {}\n", args->scene, world.size(),
               components);
    if (world.size() > 0) {
      fmt::print("cells       {} .. {}\n", geometry::toString(low), geometry::toString(high));
    }
    fmt::print("grid        {}\n", grid ? geometry::toString(*grid) : "none (ground only)");
  });
}

}  // namespace

void addSceneCommands(CLI::App& app) {
  addGenerate(app);
  addConvert(app);
  addInfo(app);
}

}  // namespace datomsim::app
