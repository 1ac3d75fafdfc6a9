// `generate`, `convert` and `info`: making, translating and describing scene files.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <nlohmann/json.hpp>

#include "arguments.h"
#include "commands.h"
#include "frontend/scene_generators.h"
#include "geometry/lattice.h"
#include "io/scene_file.h"
#include "target/target.h"
#include "world/bounds.h"

namespace datomsim::app {
namespace {

// The options every subcommand of `generate` shares: the output, and the targets to attach.
struct GenerateArguments {
  std::string out;
  // Scene files whose targets the generated scene takes (their modules are ignored).
  std::vector<std::string> targetFiles;
  // A grid target of a box of cells: size and corner cell.
  std::string targetBox, targetOrigin = "0,0,0";
  // What the modules are: "datom" or "catom3d" (the file says so).
  std::string module = "datom";
};

void addModuleKindOption(CLI::App& command, std::string& module, const std::string& help) {
  command.add_option("--module", module, help)
      ->check(CLI::IsMember({"datom", "catom3d"}))
      ->capture_default_str();
}

CLI::App* addGenerator(CLI::App& generate, const std::string& name, const std::string& help,
                       GenerateArguments& args) {
  CLI::App* command = generate.add_subcommand(name, help);
  command->add_option("-o,--out", args.out, "Scene file to write (.xml or .json)")->required();
  command->add_option("--target", args.targetFiles,
                      "Attach the targets of this scene file (.xml or .json; its modules are "
                      "ignored); may be repeated");
  CLI::Option* box = command->add_option(
      "--target-box", args.targetBox,
      "Attach a grid target: the box of X,Y,Z cells from --target-origin, x fastest");
  command->add_option("--target-origin", args.targetOrigin, "Corner cell x,y,z of --target-box")
      ->capture_default_str()
      ->needs(box);
  addModuleKindOption(*command, args.module,
                      "What the modules are: datom, or catom3d (the 3D Catom, docs/catom3d.md)");
  return command;
}

// The grid target of a box, cells in the order scene::box numbers its modules.
target::Target boxTarget(const GenerateArguments& args) {
  const geometry::Cell size = parseCell("--target-box", args.targetBox);
  const geometry::Cell origin = parseCell("--target-origin", args.targetOrigin);
  if (size.x <= 0 || size.y <= 0 || size.z <= 0) {
    throw UsageError("--target-box \"" + args.targetBox + "\" must be three positive integers");
  }
  const int64_t count = int64_t{size.x} * size.y * size.z;
  if (count > int64_t(target::kMaxListedCells)) {
    throw UsageError(fmt::format("--target-box \"{}\" holds {} cells, more than {}", args.targetBox,
                                 count, target::kMaxListedCells));
  }
  for (const int64_t high :
       {int64_t{origin.x} + size.x, int64_t{origin.y} + size.y, int64_t{origin.z} + size.z}) {
    if (high > world::kCoordinateLimit) {
      throw UsageError("--target-box leaves the supported coordinate range (docs/limits.md)");
    }
  }
  std::vector<geometry::Cell> cells;
  cells.reserve(size_t(count));
  for (int32_t z = 0; z < size.z; ++z) {
    for (int32_t y = 0; y < size.y; ++y) {
      for (int32_t x = 0; x < size.x; ++x) cells.push_back(origin + geometry::Cell{x, y, z});
    }
  }
  return unwrap(target::Target::grid(cells));
}

void writeGenerated(world::World world, const std::string& name, const GenerateArguments& args,
                    const Reporter& reporter) {
  std::vector<NamedPath> inputs;
  for (const std::string& file : args.targetFiles) inputs.push_back({"--target", file});
  // The format first: a scene file's name says it.
  unwrap(io::sceneFormatOf(args.out));
  CommandFiles files(inputs, {{"--out", args.out}});
  io::Scene scene;
  scene.world = std::move(world);
  scene.name = name;
  scene.moduleKind = *world::moduleKindNamed(args.module);
  for (const std::string& file : args.targetFiles) {
    io::Scene source = unwrap(io::readScene(file));
    if (source.targets.empty()) throw UsageError(file + ": has no targets to attach (--target)");
    for (target::Target& target : source.targets) scene.targets.push_back(std::move(target));
  }
  if (!args.targetBox.empty()) scene.targets.push_back(boxTarget(args));
  declareGridForVisibleSim(scene, args.out, reporter);
  files.write("--out", [&](std::FILE* file) { return io::writeScene(scene, args.out, file); });
  files.describe("--out", fmt::format("{} modules{}", scene.world.size(),
                                      scene.targets.empty()
                                          ? ""
                                          : fmt::format(", {} target{}", scene.targets.size(),
                                                        scene.targets.size() == 1 ? "" : "s")));
  files.commit(reporter);
}

void addGenerate(CLI::App& app, const Reporter& reporter) {
  CLI::App* generate =
      app.add_subcommand("generate", "Make a scene: box, arch, random, or a reshape case");
  generate->require_subcommand(1);
  addExample(*generate, "generate box --size 6,5,2 -o box.json");
  addReshapeGenerator(*generate, reporter);

  struct BoxArguments {
    frontend::BoxArguments box;
    GenerateArguments generate;
  };
  auto box = std::make_shared<BoxArguments>();
  CLI::App* boxCommand = addGenerator(*generate, "box", "A box of modules", box->generate);
  boxCommand->add_option("--size", box->box.size, "Size X,Y,Z in cells")->required();
  boxCommand->add_option("--origin", box->box.origin, "Corner cell x,y,z")->capture_default_str();
  boxCommand->add_option("--grid", box->box.grid, "Declare a grid X,Y,Z (default: none)");
  boxCommand->add_flag("--upright", box->box.upright,
                       "Stand straight up instead of leaning with the skew coordinates: each "
                       "layer's x and y less floor(z/2) (docs/coordinates.md); fills a grid of "
                       "its own size");
  addExample(*boxCommand, "generate box --size 10,10,4 --upright -o tall.json");
  boxCommand->callback([box, &reporter] {
    frontend::GeneratedWorld made = frontend::generateBox(box->box);
    writeGenerated(std::move(made.world), made.name, box->generate, reporter);
  });

  struct ArchArguments {
    frontend::ArchArguments arch;
    GenerateArguments generate;
  };
  auto arch = std::make_shared<ArchArguments>();
  CLI::App* archCommand = addGenerator(
      *generate, "arch", "The paper's experiment: a 7x7x2 box under an arch (section VII)",
      arch->generate);
  archCommand->add_option("--hole", arch->arch.hole, "Height of the arch's hole: 2 or 1")
      ->check(CLI::IsMember({1, 2}))
      ->capture_default_str();
  addExample(*archCommand, "generate arch --hole 1 -o arch1.json");
  archCommand->callback([arch, &reporter] {
    frontend::GeneratedWorld made = frontend::generateArch(arch->arch);
    writeGenerated(std::move(made.world), made.name, arch->generate, reporter);
  });

  struct RandomArguments {
    frontend::RandomArguments random;
    GenerateArguments generate;
  };
  auto random = std::make_shared<RandomArguments>();
  CLI::App* randomCommand =
      addGenerator(*generate, "random", "A random connected scene grown on the ground from a seed",
                   random->generate);
  randomCommand->add_option("--seed", random->random.seed, "Seed")->capture_default_str();
  randomCommand->add_option("--count", random->random.count, "Number of modules")
      ->check(kPositiveInteger)
      ->capture_default_str();
  randomCommand->add_option("--grid", random->random.grid, "Declare a grid X,Y,Z (default: none)");
  randomCommand->add_option("--height", random->random.height, "Layers the scene may use")
      ->check(kPositiveInteger)
      ->capture_default_str();
  randomCommand->add_flag("--random-orientations", random->random.orientations,
                          "Draw each module's orientation");
  addExample(*randomCommand, "generate random --count 100 --seed 7 --grid 12,12,6 -o random.json");
  randomCommand->callback([random, &reporter] {
    frontend::GeneratedWorld made = frontend::generateRandom(random->random);
    writeGenerated(std::move(made.world), made.name, random->generate, reporter);
  });
}

void addConvert(CLI::App& app, const Reporter& reporter) {
  struct Arguments {
    std::string in, out, module;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command =
      app.add_subcommand("convert", "Convert a scene between VisibleSim XML and JSON");
  command->add_option("scene", args->in, "Scene file to read (.xml or .json)")->required();
  command->add_option("-o,--out", args->out, "Scene file to write (.xml or .json)")->required();
  command
      ->add_option("--module", args->module,
                   "Make the modules datom or catom3d (default: what the file says)")
      ->check(CLI::IsMember({"datom", "catom3d"}));
  addExample(*command, "convert scenes/paper-arch-hole1.json -o arch1.xml");
  command->callback([args, &reporter] {
    unwrap(io::sceneFormatOf(args->out));
    CommandFiles files({{"scene", args->in}}, {{"--out", args->out}});
    io::Scene scene = unwrap(io::readScene(args->in));
    if (!args->module.empty()) scene.moduleKind = *world::moduleKindNamed(args->module);
    declareGridForVisibleSim(scene, args->out, reporter);
    files.write("--out", [&](std::FILE* file) { return io::writeScene(scene, args->out, file); });
    files.describe(
        "--out",
        fmt::format("{} modules{}", scene.world.size(),
                    scene.moduleKind == world::ModuleKind::kCatom3D ? " (3D Catoms)" : ""));
    files.commit(reporter);
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
      const uint16_t around = world.neighbourMask(module.cell);
      for (int d = 0; d < geometry::kDirectionCount; ++d) {
        if (!(around & (1u << d))) continue;
        const world::Module* next = world.neighbour(module, d);
        const auto index = uint32_t(next - world.modules().data());
        if (!seen[index]) {
          seen[index] = true;
          stack.push_back(index);
        }
      }
    }
  }
  return components;
}

// What `info` reports of a target: a later command that needs the cell count to equal the
// module count refuses then, not here.
struct TargetSummary {
  std::string format;
  size_t cells = 0;
  size_t filled = 0;
};

std::vector<TargetSummary> summarizeTargets(const io::Scene& scene, const std::string& path) {
  std::vector<TargetSummary> summaries;
  for (size_t i = 0; i < scene.targets.size(); ++i) {
    const target::Target& target = scene.targets[i];
    const Result<size_t> cells = target.count();
    if (!cells) throw UsageError(fmt::format("{}: targets[{}]: {}", path, i, cells.error()));
    summaries.push_back(
        {std::string(target::formatName(target.format())), *cells, target.filledIn(scene.world)});
  }
  return summaries;
}

void addInfo(CLI::App& app) {
  struct Arguments {
    std::string scene;
    bool json = false;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "info", "Module count, bounds, connected components and targets of a scene");
  command->add_option("scene", args->scene, "Scene file (.xml or .json)")->required();
  command->add_flag("--json", args->json, "Print one JSON object");
  addExample(*command, "info scenes/reshape-heap.json");
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
    out["module"] = world::toString(scene.moduleKind);
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
    const std::vector<TargetSummary> targets = summarizeTargets(scene, args->scene);
    out["targets"] = nlohmann::ordered_json::array();
    for (const TargetSummary& target : targets) {
      out["targets"].push_back({{"format", target.format},
                                {"cells", target.cells},
                                {"filled", target.filled},
                                {"cells_equal_modules", target.cells == world.size()}});
    }
    if (args->json) {
      fmt::print("{}\n", out.dump());
      return;
    }
    fmt::print("scene       {}\nmodules     {} ({})\ncomponents  {}\n", args->scene, world.size(),
               world::toString(scene.moduleKind), components);
    if (world.size() > 0) {
      fmt::print("cells       {} .. {}\n", geometry::toString(low), geometry::toString(high));
    }
    fmt::print("grid        {}\n", grid ? geometry::toString(*grid) : "none (ground only)");
    for (size_t i = 0; i < targets.size(); ++i) {
      const TargetSummary& target = targets[i];
      fmt::print("{:<12}{}, {} cells, {} filled; {}\n", fmt::format("target {}", i), target.format,
                 target.cells, target.filled,
                 target.cells == world.size()
                     ? "as many cells as modules"
                     : fmt::format("{} cells for {} modules", target.cells, world.size()));
    }
  });
}

}  // namespace

void addSceneCommands(CLI::App& app, const Reporter& reporter) {
  addGenerate(app, reporter);
  addConvert(app, reporter);
  addInfo(app);
}

}  // namespace datomsim::app
