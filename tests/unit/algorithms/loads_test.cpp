// The distributed load solver (the module program `loads`) against the centralised one
// (mechanics::solveLoads, factorised: exact to rounding) on random connected scenes and a
// cantilever: every module's largest latch force and moment and its smallest safety factor agree
// within kAgreement (docs/mechanics.md, "The distributed solver"). The simulator checks its
// invariants after every event; a violation would be the run's failure.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <string_view>

#include "experiment/run.h"
#include "mechanics/load_model.h"
#include "mechanics/load_solver.h"
#include "scene/random_scene.h"
#include "support/rule_table.h"
#include "support/world_builder.h"
#include "unit/mechanics/mechanics_scenes.h"

namespace datomsim {
namespace {

// The agreement docs/mechanics.md states: every module's force and moment within this fraction
// of the scene's largest, every safety factor within this fraction of itself, at the default
// tolerance (a relative residual of 1e-10).
constexpr double kAgreement = 1e-8;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// What a module reports: its latches' largest force (N) and moment (N m), their smallest safety.
struct Worst {
  double force = 0;
  double moment = 0;
  double safety = kInfinity;
};

std::map<Cell, Worst> centralised(const world::World& world) {
  const mechanics::LoadModel model = *mechanics::buildLoadModel(world, {});
  const Result<mechanics::LoadSolution> solution = mechanics::solveLoads(model);
  EXPECT_TRUE(solution.ok());
  std::map<Cell, Worst> worst;
  for (const mechanics::Node& node : model.nodes) worst[node.cell] = {};
  for (size_t k = 0; k < model.beams.size(); ++k) {
    const elastic::LatchLoad& load = solution->latches[k];
    for (const uint32_t end : {model.beams[k].a, model.beams[k].b}) {
      Worst& w = worst[model.nodes[end].cell];
      w.force = std::max(w.force, geometry::norm(load.force));
      w.moment = std::max(w.moment, geometry::norm(load.moment));
      w.safety = std::min(w.safety, load.safety);
    }
  }
  return worst;
}

struct Distributed {
  std::map<Cell, Worst> modules;
  double iterations = 0;
  double residual = 0;
  double converged = 0;
  double tookPart = 0;  // the modules the tree reached, as the root counted them
  std::map<std::string, uint64_t, std::less<>> messages;
};

Distributed distributed(world::World world, const Cell& root,
                        std::map<std::string, std::string> parameters = {}, Time jitter = 0) {
  experiment::RunRequest request;
  request.program = "loads";
  request.parameters = std::move(parameters);
  request.parameters["root"] = toString(root);
  request.simulation.messageJitter = jitter;
  const auto run = experiment::runProgram(std::move(world), testing::paperRules(), request);
  Distributed out;
  EXPECT_TRUE(run.ok()) << run.error();
  if (!run.ok()) return out;
  EXPECT_FALSE(run->failure) << *run->failure;
  for (const auto& [cell, value] : run->report.cellValues("force")) out.modules[cell].force = value;
  for (const auto& [cell, value] : run->report.cellValues("moment")) {
    out.modules[cell].moment = value;
  }
  for (const auto& [cell, value] : run->report.cellValues("safety")) {
    out.modules[cell].safety = value;
  }
  for (const auto& [key, field] :
       {std::pair{"iterations", &out.iterations}, std::pair{"residual", &out.residual},
        std::pair{"converged", &out.converged}, std::pair{"modules", &out.tookPart}}) {
    const auto values = run->report.cellValues(key);
    // No residual when nothing holds the ensemble: the iteration never started.
    if (values.empty() && std::string_view(key) == "residual") continue;
    EXPECT_EQ(values.size(), 1u) << key;
    if (values.size() == 1) {
      EXPECT_EQ(values[0].first, root) << key << " is the root's";
      *field = values[0].second;
    }
  }
  out.messages = run->statistics.messagesByType;
  return out;
}

// The largest disagreement, as a fraction of the scene's largest force and moment, and of each
// finite safety factor.
double disagreement(const std::map<Cell, Worst>& expected, const std::map<Cell, Worst>& found) {
  double forceScale = 0, momentScale = 0;
  for (const auto& [cell, worst] : expected) {
    forceScale = std::max(forceScale, worst.force);
    momentScale = std::max(momentScale, worst.moment);
  }
  double worst = 0;
  for (const auto& [cell, want] : expected) {
    const auto got = found.find(cell);
    if (got == found.end()) return kInfinity;
    worst = std::max(worst, std::abs(got->second.force - want.force) / forceScale);
    worst = std::max(worst, std::abs(got->second.moment - want.moment) / momentScale);
    if (std::isfinite(want.safety)) {
      worst = std::max(worst, std::abs(got->second.safety - want.safety) / want.safety);
    } else if (std::isfinite(got->second.safety)) {
      return kInfinity;
    }
  }
  return worst;
}

TEST(DistributedLoads, OnRandomScenesTheLoadsAreTheCentralisedSolversWithinTheStatedAgreement) {
  scene::RandomOptions options;
  options.maxHeight = 5;
  options.randomOrientations = true;
  for (const uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
    const auto world = scene::random(seed, 70, options);
    ASSERT_TRUE(world.ok()) << world.error();
    const auto expected = centralised(*world);
    // The first module (on the ground) leads, but in one scene the last one off the ground does:
    // any module may lead.
    Cell root = world->modules()[0].cell;
    for (const world::Module& module : world->modules()) {
      if (seed == 3 && module.cell.z > 0) root = module.cell;
    }
    if (seed == 3) {
      EXPECT_GT(root.z, 0);
    }
    const Distributed found = distributed(*world, root, {}, seed == 2 ? 7 * kMillisecond : 0);
    EXPECT_EQ(found.converged, 1) << "seed " << seed;
    EXPECT_LE(found.residual, 1e-10) << "seed " << seed;
    EXPECT_EQ(found.modules.size(), world->size()) << "seed " << seed;
    EXPECT_EQ(found.tookPart, double(world->size())) << "seed " << seed;
    EXPECT_LT(disagreement(expected, found.modules), kAgreement) << "seed " << seed;
  }
}

TEST(DistributedLoads, ACantileversRootCarriesItsArmAsTheCentralisedSolverSays) {
  const world::World world = testing::cantilever(3, 5);
  const auto expected = centralised(world);
  const Distributed found = distributed(world, {0, 0, 0});
  EXPECT_EQ(found.converged, 1);
  EXPECT_LT(disagreement(expected, found.modules), kAgreement);
  // The arm's first module carries the moment of the five weights about the root latch,
  // m g L n^2 / 2 (docs/mechanics.md, "Checks").
  const mechanics::LoadModel model = *mechanics::buildLoadModel(world, {});
  const double weight = model.moduleMass * 9.81;
  const double rootMoment = weight * 0.02 * 25 / 2;
  EXPECT_NEAR(found.modules.at({1, 0, 2}).moment, rootMoment, kAgreement * rootMoment);
}

TEST(DistributedLoads, MessagesAreTheAlgorithmsCountsPerIteration) {
  const world::World world = testing::cantilever(4, 4);
  const Distributed found = distributed(world, {0, 0, 0});
  const uint64_t n = world.size(), iterations = uint64_t(found.iterations);
  const mechanics::LoadModel model = *mechanics::buildLoadModel(world, {});
  // Latches between two free modules carry the search directions; a free module's every latch
  // carries its displacement at the end.
  uint64_t freeLatches = 0, freeEnds = 0;
  for (const mechanics::Beam& beam : model.beams) {
    const bool a = !model.nodes[beam.a].supported, b = !model.nodes[beam.b].supported;
    freeLatches += a && b ? 1 : 0;
    freeEnds += (a ? 1 : 0) + (b ? 1 : 0);
  }
  EXPECT_GT(iterations, 0u);
  EXPECT_EQ(found.messages.at("LoadExploreMsg") + found.messages.at("LoadEchoMsg"),
            2 * model.beams.size());
  EXPECT_EQ(found.messages.at("LoadEchoMsg"), n - 1);
  for (const char* tree : {"LoadStepMsg", "LoadCurvatureMsg", "LoadAlphaMsg", "LoadResidualMsg"}) {
    EXPECT_EQ(found.messages.at(tree), iterations * (n - 1)) << tree;
  }
  EXPECT_EQ(found.messages.at("LoadDirectionMsg"), iterations * 2 * freeLatches);
  EXPECT_EQ(found.messages.at("LoadDoneMsg"), n - 1);
  EXPECT_EQ(found.messages.at("LoadDisplacementMsg"), freeEnds);
}

TEST(DistributedLoads, TranslatingASceneAlongTheGroundChangesNothing) {
  const world::World world = *scene::random(8, 50);
  world::World moved;
  const Cell shift{7, -4, 0};
  for (const world::Module& module : world.modules()) {
    world::Module copy = module;
    copy.cell = module.cell + shift;
    ASSERT_TRUE(moved.add(copy).ok());
  }
  moved.latchAllNeighbours();
  const Cell root = world.modules()[0].cell;
  const Distributed here = distributed(world, root);
  const Distributed there = distributed(std::move(moved), root + shift);
  EXPECT_EQ(here.iterations, there.iterations);
  EXPECT_EQ(here.messages, there.messages);
  ASSERT_EQ(here.modules.size(), there.modules.size());
  for (const auto& [cell, worst] : here.modules) {
    const Worst& other = there.modules.at(cell + shift);
    // The modules see only directions and whether they stand on the ground: the same numbers.
    EXPECT_EQ(other.force, worst.force) << cell;
    EXPECT_EQ(other.moment, worst.moment) << cell;
    EXPECT_EQ(other.safety, worst.safety) << cell;
  }
}

TEST(DistributedLoads, ATooShortIterationSaysItDidNotConvergeAndReportsNoLoads) {
  const world::World world = *scene::random(2, 40);
  const Distributed found = distributed(world, world.modules()[0].cell, {{"max-iterations", "3"}});
  EXPECT_EQ(found.iterations, 3);
  EXPECT_EQ(found.converged, 0);
  EXPECT_GT(found.residual, 1e-10);
  EXPECT_TRUE(found.modules.empty());
}

TEST(DistributedLoads, AnEnsembleOffTheGroundIsHeldByNothingAndReportsNoLoads) {
  testing::WorldBuilder builder;
  for (int z = 1; z <= 3; ++z) builder.module({0, 0, z});
  const Distributed found = distributed(builder.build(), {0, 0, 2});
  EXPECT_EQ(found.converged, 0);
  EXPECT_EQ(found.iterations, 0);
  EXPECT_TRUE(found.modules.empty());
  EXPECT_EQ(found.messages.count("LoadStepMsg"), 0u);
}

TEST(DistributedLoads, RefusesBadParametersNamingThem) {
  const world::World world = testing::cantilever(2, 2);
  struct Case {
    std::map<std::string, std::string> parameters;
    std::string says;
  };
  for (const Case& c : {
           Case{{{"density", "-1240"}},
                "the density must be a positive number (kg/m^3), not -1240"},
           Case{{{"poisson-ratio", "0.5"}}, "Poisson's ratio must lie in (-1, 0.5), not 0.5"},
           Case{{{"gravity", "0,-9.81"}}, "parameter gravity: \"0,-9.81\" is not three numbers"},
           Case{{{"gravity", "0,0,0"}}, "gravity must not be zero"},
           Case{{{"tolerance", "0"}}, "parameter tolerance of program loads: \"0\" is out of"},
           Case{{{"max-iterations", "0"}}, "parameter max-iterations of program loads"},
       }) {
    experiment::RunRequest request;
    request.program = "loads";
    request.parameters = c.parameters;
    request.parameters["root"] = "0,0,0";
    const auto run = experiment::runProgram(world, testing::paperRules(), request);
    ASSERT_FALSE(run.ok()) << c.says;
    EXPECT_NE(run.error().find(c.says), std::string::npos) << run.error();
  }
}

}  // namespace
}  // namespace datomsim
