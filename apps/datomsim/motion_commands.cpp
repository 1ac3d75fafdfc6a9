// `reach`, `moves` and `verify`: the motion rules from the command line.
#include <fmt/format.h>

#include <unistd.h>
#include <CLI/CLI.hpp>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <tuple>

#include "arguments.h"
#include "catom3d/catom_rolls.h"
#include "commands.h"
#include "frontend/motion_json.h"
#include "geometry/lattice.h"
#include "io/scene_file.h"
#include "motion/datom_rules.h"
#include "motion/reach.h"

namespace datomsim::app {
namespace {

// Theorem 2 for each model asked; throws when one fails it.
void verifyModels(const world::World& world,
                  const std::vector<std::unique_ptr<const motion::MotionModel>>& models) {
  size_t failures = 0;
  for (const auto& model : models) {
    const auto report = model->checkBidirectionality(world);
    fmt::print("{}: {} cells, {} motions, {} counterexamples\n", model->describe(),
               report.cellsChecked, report.motionsChecked, report.counterexamples.size());
    for (const auto& counterexample : report.counterexamples) {
      const motion::Motion& m = counterexample.forward;
      fmt::print("  {} -> {} ({}) has no way back\n", geometry::toString(m.from),
                 geometry::toString(m.goal), model->describe(m));
    }
    failures += report.counterexamples.size();
  }
  if (failures > 0) throw CheckFailed(fmt::format("{} counterexamples to theorem 2", failures));
}

void addReach(CLI::App& app, const Reporter& reporter) {
  struct Arguments {
    std::string scene, goal, start, out;
    PictureRequest pictures;
    RuleArguments rules;
    ModuleArguments module;
    int threads = 0;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "reach", "Distances in motions from every reachable cell to a goal (paper, section VII)");
  command->add_option("scene", args->scene, "Scene file (.xml or .json)")->required();
  command->add_option("--goal", args->goal, "Goal cell x,y,z; a module there is the mobile")
      ->required();
  command->add_option("--start", args->start,
                      "Also follow the gradient from this cell and draw the path; the mobile is "
                      "the module there, else the one at the goal (as for run)");
  addRuleOptions(*command, args->rules);
  args->module.addTo(*command);
  command
      ->add_option("--threads", args->threads,
                   "Threads the distances are searched on, frontier by frontier (default: every "
                   "core; the map is the same for any number)")
      ->check(kPositiveInteger);
  addOutputOption(*command, args->out);
  PictureRequest& asked = args->pictures;
  command->add_option("--png", asked.png, "Write the distance map as a PNG picture");
  command->add_option("--svg", asked.svg, "Write the distance map as an SVG picture");
  command
      ->add_option("--scale", asked.scale,
                   "Pixels per cell in the pictures, 2..256 (default 48, lowered to fit "
                   "--max-size)")
      ->check(CLI::Range(2, 256));
  command
      ->add_option("--max-size", asked.maxSize,
                   "Longest side of a picture in pixels: a larger one is drawn at a smaller scale "
                   "(default 4000 without --scale, no limit with it; 0: no limit). A picture "
                   "drawn smaller than asked, or whose cells are too small for their numbers, "
                   "says so under its title and on standard error")
      ->check(kNonNegativeInteger);
  command
      ->add_option("--palette", asked.palette,
                   "How distances are coloured in the pictures: paper (the paper's ten colours, "
                   "then a dark ramp), continuous (one scale from the goal to the farthest cell), "
                   "or auto: paper while every distance is below 25")
      ->check(CLI::IsMember({"auto", "paper", "continuous"}))
      ->capture_default_str();
  addExample(*command,
             "reach scenes/paper-arch-hole1.json --goal 6,5,2 --start 0,0,2 --png arch1.png");
  command->callback([args, &reporter] {
    const PictureRequest& pictures = args->pictures;
    std::vector<NamedPath> outputs = {{"--out", args->out}};
    frontend::addPictureOutputs(pictures, outputs);
    CommandFiles files({{"scene", args->scene}}, outputs);
    frontend::refuseMisnamedPictures(pictures.png, pictures.svg);
    const geometry::Cell goal = parseCell("--goal", args->goal);
    const std::optional<geometry::Cell> start =
        args->start.empty() ? std::nullopt : std::optional(parseCell("--start", args->start));
    io::Scene scene = unwrap(io::readScene(args->scene));
    const MotionChoice model = args->module.modelFor(scene, args->rules);
    const ReachOutput reached = reachOnScene(std::move(scene), goal, start, model, args->threads);
    const std::string title = fmt::format("{}: distances to {} ({})", args->scene,
                                          geometry::toString(goal), describe(model));
    writePictures(reached.fixed, reached.mobileTakenOut, reached.map, reached.path, title, pictures,
                  files, reporter);
    files.write("--out", [&](std::FILE* file) {
      return frontend::writeReachJson(reached.map, reached.path, model, file);
    });
    files.commit(reporter);
  });
}

void addMoves(CLI::App& app, const Reporter& reporter) {
  struct Arguments {
    std::string scene, at, out, format = "auto";
    RuleArguments rules;
    ModuleArguments module;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "moves", "Every rule of every pivot around a cell, valid or refused with its reason");
  command->add_option("scene", args->scene, "Scene file (.xml or .json)")->required();
  command->add_option("--at", args->at, "The mobile's cell x,y,z; a module there is the mobile")
      ->required();
  addRuleOptions(*command, args->rules);
  args->module.addTo(*command);
  command
      ->add_option("--format", args->format,
                   "table (for a person), json, or auto: a table on a terminal, JSON otherwise "
                   "and always in --out files")
      ->check(CLI::IsMember({"auto", "table", "json"}))
      ->capture_default_str();
  addOutputOption(*command, args->out);
  addExample(*command, "moves scenes/paper-arch-hole1.json --at 2,2,3");
  command->callback([args, &reporter] {
    CommandFiles files({{"scene", args->scene}}, {{"--out", args->out}});
    const geometry::Cell at = parseCell("--at", args->at);
    const io::Scene scene = unwrap(io::readScene(args->scene));
    const MotionChoice model = args->module.modelFor(scene, args->rules);
    const bool toTerminal = (args->out.empty() || args->out == "-") && isatty(fileno(stdout));
    const bool asTable = args->format == "table" || (args->format == "auto" && toTerminal);
    files.write("--out", frontend::movesOnScene(scene, "--at", at, model, asTable));
    files.commit(reporter);
  });
}

void addVerify(CLI::App& app) {
  struct Arguments {
    std::string scene;
    std::vector<std::string> rules = {"paper", "strict"};
    std::vector<std::string> attachment = {"on", "off"};
    std::string module;
    std::vector<std::string> rolling = {"symmetric"};
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "verify",
      "Check theorem 2 (bidirectionality) on a scene: every module fixed, the mobile imagined at "
      "every free cell next to them; exits 1 if a counterexample is found");
  command->add_option("scene", args->scene, "Scene file (.xml or .json)")->required();
  command->add_option("--rules", args->rules, "Rule tables to check")
      ->check(CLI::IsMember({"paper", "strict"}))
      ->capture_default_str();
  command->add_option("--attachment", args->attachment, "Attachment settings to check")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  command
      ->add_option("--module", args->module,
                   "The module whose motions are checked: datom or catom3d (default: the scene "
                   "file's)")
      ->check(CLI::IsMember({"datom", "catom3d"}));
  command
      ->add_option("--rolling", args->rolling,
                   "The 3D Catom's rule sets to check: symmetric, visiblesim (VisibleSim's own "
                   "checks, which theorem 2 does not hold for)")
      ->check(CLI::IsMember({"symmetric", "visiblesim"}))
      ->capture_default_str();
  addExample(*command, "verify scenes/paper-arch-hole1.json");
  command->callback([args, command] {
    const io::Scene scene = unwrap(io::readScene(args->scene));
    const world::ModuleKind kind = kindFor(args->module, scene);
    refuseOtherKindsOptions(*command, kind, {"--rules", "--attachment"});
    const motion::RuleTable table;
    std::vector<std::unique_ptr<const motion::MotionModel>> models;
    if (kind == world::ModuleKind::kCatom3D) {
      for (const std::string& rolling : args->rolling) {
        models.push_back(std::make_unique<catom3d::CatomRolls>(*catom3d::rollRulesNamed(rolling)));
      }
    } else {
      for (const std::string& rules : args->rules) {
        for (const std::string& attachment : args->attachment) {
          models.push_back(
              std::make_unique<motion::DatomRules>(table, parseRuleOptions(rules, attachment)));
        }
      }
    }
    verifyModels(scene.world, models);
  });
}

}  // namespace

void addMotionCommands(CLI::App& app, const Reporter& reporter) {
  addReach(app, reporter);
  addMoves(app, reporter);
  addVerify(app);
}

}  // namespace datomsim::app
