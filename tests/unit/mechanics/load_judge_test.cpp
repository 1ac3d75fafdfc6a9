// The judge of changes under gravity against the whole model solved on the changed world: the same
// latch found overloaded at the same limit (the pieces it solves are exact, not approximations),
// a mobile at the tip of an arm loading its root as a longer arm, pieces held by nothing, tipping,
// and the pieces kept small on a floor.
#include "mechanics/load_judge.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "geometry/lattice.h"
#include "mechanics/load_model.h"
#include "mechanics/load_solver.h"
#include "unit/mechanics/mechanics_scenes.h"

namespace datomsim::mechanics {
namespace {

using elastic::LoadParameters;
using testing::WorldBuilder;

uint32_t indexOf(const world::World& world, const geometry::Cell& cell) {
  return *world.indexOf(world.moduleAt(cell)->id);
}

// The whole model of a world solved: its least safe latch's safety and its two modules' ids.
struct Weakest {
  double safety = 0;
  ModuleId a, b;
};

Weakest weakestOf(const world::World& world, const LoadParameters& parameters) {
  Result<LoadModel> model = buildLoadModel(world, parameters);
  EXPECT_TRUE(model.ok()) << model.error();
  Result<LoadSolution> solution = solveLoads(*model);
  EXPECT_TRUE(solution.ok()) << solution.error();
  Weakest weakest{1e300, {}, {}};
  for (size_t k = 0; k < model->beams.size(); ++k) {
    if (solution->latches[k].safety < weakest.safety) {
      const ModuleId a = model->nodes[model->beams[k].a].module;
      const ModuleId b = model->nodes[model->beams[k].b].module;
      weakest = {solution->latches[k].safety, std::min(a, b), std::max(a, b)};
    }
  }
  return weakest;
}

// The parameters with both latch limits scaled so that a latch of safety `safety` under the
// defaults has safety `factor`.
LoadParameters scaledSoThat(double safety, double factor) {
  LoadParameters parameters;
  parameters.latchForce *= factor / safety;
  parameters.latchMoment *= factor / safety;
  return parameters;
}

// Four modules alone on the ground far around: a footing wide enough that nothing tips, which
// carries no load (their latches hold nothing) and changes none.
void addWideFooting(WorldBuilder& builder) {
  for (const geometry::Cell& cell :
       {geometry::Cell{-30, -30, 0}, {30, -30, 0}, {-30, 30, 0}, {30, 30, 0}}) {
    builder.module(cell);
  }
}

// testing::cantilever on a wide footing: a column of `height`, an arm of `arm` from its top.
world::World footedCantilever(int height, int arm) {
  WorldBuilder builder;
  for (int z = 0; z < height; ++z) builder.module({0, 0, z});
  for (int k = 1; k <= arm; ++k) builder.module({k, 0, height - 1});
  addWideFooting(builder);
  return builder.build();
}

// An arm of 4 on a column of 3 on its wide footing, and a module alone on the ground far away
// (the mover of the tests).
world::World armAndALoneModule() {
  WorldBuilder builder;
  for (int z = 0; z < 3; ++z) builder.module({0, 0, z});
  for (int k = 1; k <= 4; ++k) builder.module({k, 0, 2});
  builder.module({20, 0, 0});
  addWideFooting(builder);
  return builder.build();
}

std::string latchName(const Weakest& weakest) {
  return "latch " + std::to_string(weakest.a.value) + "-" + std::to_string(weakest.b.value) + " ";
}

// Every latch of `index` but the one towards `keep`, both ends.
std::vector<world::BrokenLatch> allLatchesBut(const world::World& world, uint32_t index,
                                              uint32_t keep) {
  std::vector<world::BrokenLatch> broken;
  const world::Module& module = world.modules()[index];
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    const world::Module* other = world.neighbour(module, direction);
    if (!other || !world.isLatched(module, direction) || *world.indexOf(other->id) == keep) {
      continue;
    }
    world::addBrokenLatch(world, module, direction, broken);
  }
  return broken;
}

TEST(LoadJudge, FindsTheSameOverloadedLatchAsTheWholeModelOfTheChangedWorld) {
  // A box of two layers over the ground is one piece: the judge solves all of it.
  WorldBuilder builder;
  builder.box({0, 0, 0}, {4, 4, 3});
  const world::World world = builder.build();
  const uint32_t mobile = indexOf(world, {1, 2, 2});
  const uint32_t pivot = indexOf(world, {2, 2, 2});
  const std::vector<world::BrokenLatch> released = allLatchesBut(world, mobile, pivot);
  ASSERT_FALSE(released.empty());
  const std::array<geometry::Cell, 1> place = {geometry::Cell{1, 2, 2}};
  const Mover hanging{mobile, pivot, place, {}};

  // The same change made on a copy of the world, solved whole.
  world::World changed = world;
  for (const world::BrokenLatch& latch : released) {
    const world::Module& module = changed.modules()[latch.module];
    ASSERT_TRUE(
        changed.setLatched(module.id, module.orientation.worldDirection(latch.connector), false)
            .ok());
  }
  const Weakest weakest = weakestOf(changed, {});
  ASSERT_LT(weakest.safety, 1e300);

  LoadJudge tight(scaledSoThat(weakest.safety, 0.999));
  const auto refused = tight.judge(world, {released, {}, hanging});
  ASSERT_TRUE(refused.has_value());
  EXPECT_NE(refused->text.find(latchName(weakest) + "would carry"), std::string::npos)
      << refused->text;
  LoadJudge loose(scaledSoThat(weakest.safety, 1.001));
  const auto allowed = loose.judge(world, {released, {}, hanging});
  EXPECT_FALSE(allowed.has_value()) << allowed->text;
  EXPECT_EQ(loose.counts().changes, 1u);
  EXPECT_EQ(loose.counts().refused, 0u);
  EXPECT_EQ(tight.counts().refused, 1u);
}

TEST(LoadJudge, AMobileHangingAtTheTipOfAnArmLoadsItsRootAsALongerArmWould) {
  // An arm of 4 on a column of 3, and a module alone on the ground far away; it hangs from the
  // arm's tip, one cell further out: the arm of 5, same ids but for the footing's.
  const world::World world = armAndALoneModule();
  const Weakest longer = weakestOf(footedCantilever(3, 5), {});
  const std::array<geometry::Cell, 1> place = {geometry::Cell{5, 0, 2}};
  const Mover hanging{indexOf(world, {20, 0, 0}), indexOf(world, {4, 0, 2}), place, {}};

  LoadJudge tight(scaledSoThat(longer.safety, 0.999));
  const auto refused = tight.judge(world, {{}, {}, hanging});
  ASSERT_TRUE(refused.has_value());
  EXPECT_NE(refused->text.find(latchName(longer) + "would carry"), std::string::npos)
      << refused->text;
  EXPECT_EQ(refused->moverAt, (geometry::Cell{5, 0, 2}));
  LoadJudge loose(scaledSoThat(longer.safety, 1.001));
  EXPECT_FALSE(loose.judge(world, {{}, {}, hanging}).has_value());

  // Its way from above the tip to beyond it: two cases of one model, the second refused.
  const std::array<geometry::Cell, 2> way = {geometry::Cell{4, 0, 3}, geometry::Cell{5, 0, 2}};
  const auto onTheWay = tight.judge(world, {{}, {}, Mover{hanging.module, hanging.pivot, way, {}}});
  ASSERT_TRUE(onTheWay.has_value());
  EXPECT_EQ(onTheWay->moverAt, (geometry::Cell{5, 0, 2}));
  EXPECT_EQ(tight.counts().solves, 2u);
}

TEST(LoadJudge, APlaceOnTheWayIsWeighedAsACaseOfItsOwnWouldBe) {
  // The arm of 4 on a column of 3; the mover hangs from its tip above it (a cell), then on its way
  // half a spacing further out than any cell around (a place between): the judge weighs the places
  // between by superposition, and must find what the place solved alone gives.
  const world::World world = armAndALoneModule();
  const LoadParameters defaults;
  const double spacing = 2.0 * defaults.radius;
  const uint32_t pivot = indexOf(world, {4, 0, 2});
  const geometry::Vec3 pivotCentre = geometry::worldPosition({4, 0, 2}, spacing);
  const std::array<geometry::Vec3, 1> between = {pivotCentre +
                                                 geometry::Vec3{1.5 * spacing, 0.2 * spacing, 0}};

  // The place solved alone: the mover's weight and its moment about the pivot, on the whole model.
  Result<LoadModel> model = buildLoadModel(world, defaults);
  ASSERT_TRUE(model.ok()) << model.error();
  uint32_t pivotNode = 0;
  while (model->nodes[pivotNode].module != world.modules()[pivot].id) ++pivotNode;
  const geometry::Vec3 weight = defaults.gravity * model->moduleMass;
  const std::vector<std::vector<NodeLoad>> alone = {
      {{pivotNode, weight, geometry::cross(between[0] - pivotCentre, weight)}}};
  auto solved = solveLoadCases(*model, alone);
  ASSERT_TRUE(solved.ok()) << solved.error();
  Weakest exact{1e300, {}, {}};
  for (size_t k = 0; k < model->beams.size(); ++k) {
    if (solved->front().latches[k].safety < exact.safety) {
      const ModuleId a = model->nodes[model->beams[k].a].module;
      const ModuleId b = model->nodes[model->beams[k].b].module;
      exact = {solved->front().latches[k].safety, std::min(a, b), std::max(a, b)};
    }
  }
  ASSERT_LT(exact.safety, 1e300);

  const std::array<geometry::Cell, 1> above = {geometry::Cell{4, 0, 3}};
  const Mover mover{indexOf(world, {20, 0, 0}), pivot, above, between};
  LoadJudge tight(scaledSoThat(exact.safety, 0.999));
  const auto refused = tight.judge(world, {{}, {}, mover});
  ASSERT_TRUE(refused.has_value());
  EXPECT_NE(refused->text.find(latchName(exact) + "would carry"), std::string::npos)
      << refused->text;
  EXPECT_EQ(refused->moverBetween, size_t(0));
  EXPECT_FALSE(refused->moverAt.has_value());
  LoadJudge loose(scaledSoThat(exact.safety, 1.001));
  const auto allowed = loose.judge(world, {{}, {}, mover});
  EXPECT_FALSE(allowed.has_value()) << allowed->text;
  // Without the place between, the tight limits let the way pass: the ends alone miss it.
  EXPECT_FALSE(tight.judge(world, {{}, {}, Mover{mover.module, pivot, above, {}}}).has_value());
}

TEST(LoadJudge, RefusesToLetGoOfTheOnlyLatchThatHoldsAPiece) {
  const world::World world = testing::cantilever(3, 2);
  const uint32_t top = indexOf(world, {0, 0, 2});
  const uint32_t root = indexOf(world, {1, 0, 2});
  std::vector<world::BrokenLatch> released;
  const auto direction =
      geometry::directionOfOffset(geometry::Cell{1, 0, 2} - geometry::Cell{0, 0, 2});
  world::addBrokenLatch(world, world.modules()[top], *direction, released);
  ASSERT_EQ(released.size(), 2u);
  EXPECT_TRUE(released[0].module == root || released[1].module == root);
  LoadJudge judge(LoadParameters{});
  const auto refused = judge.judge(world, {released, {}, std::nullopt});
  ASSERT_TRUE(refused.has_value());
  EXPECT_NE(refused->text.find("nothing would hold it"), std::string::npos) << refused->text;
}

TEST(LoadJudge, RefusesAChangeThatTipsTheEnsembleAndCheckAtRestRefusesASceneThatTips) {
  // Latches too strong to break: only tipping can refuse. A 3 by 3 block on the ground along -x,
  // a module on its end and an arm along +x from it: the longest arm that stands, then one more.
  LoadParameters strong;
  strong.latchForce = 1e6;
  strong.latchMoment = 1e6;
  auto armOverBlock = [](int arm, bool mover) {
    WorldBuilder builder;
    builder.box({-2, -1, 0}, {3, 3, 1});
    builder.module({0, 0, 1});
    for (int k = 1; k <= arm; ++k) builder.module({k, 0, 1});
    if (mover) builder.module({-2, 0, 1});
    return builder.build();
  };
  int standing = 0;
  while (standing < 12 && checkAtRest(armOverBlock(standing + 1, false), strong).ok()) ++standing;
  ASSERT_GE(standing, 1);
  ASSERT_LT(standing, 12);
  const Status tips = checkAtRest(armOverBlock(standing + 1, false), strong);
  ASSERT_FALSE(tips.ok());
  EXPECT_NE(tips.error().find("tips"), std::string::npos) << tips.error();

  // The same arm made by a module that stands on the block's far end and hangs at the tip.
  const world::World world = armOverBlock(standing, true);
  const Status stands = checkAtRest(world, strong);
  ASSERT_TRUE(stands.ok()) << stands.error();
  const uint32_t mover = indexOf(world, {-2, 0, 1});
  const std::vector<world::BrokenLatch> released = allLatchesBut(world, mover, UINT32_MAX);
  const std::array<geometry::Cell, 1> place = {geometry::Cell{standing + 1, 0, 1}};
  const Mover hanging{mover, indexOf(world, {standing, 0, 1}), place, {}};
  ASSERT_EQ(world.moduleAt({standing + 1, 0, 1}), nullptr);
  LoadJudge judge(strong);
  const auto refused = judge.judge(world, {released, {}, hanging});
  ASSERT_TRUE(refused.has_value());
  EXPECT_NE(refused->text.find("the ensemble would tip"), std::string::npos) << refused->text;
}

TEST(LoadJudge, SolvesOnlyThePieceAroundTheChangeOnAFloor) {
  // Two modules on a floor of 100, far apart: each is a piece of its own over the held floor.
  WorldBuilder builder;
  builder.box({0, 0, 0}, {10, 10, 1});
  builder.module({2, 2, 1});
  builder.module({7, 7, 1});
  const world::World world = builder.build();
  const uint32_t mover = indexOf(world, {2, 2, 1});
  const uint32_t pivot = indexOf(world, {2, 2, 0});
  const std::vector<world::BrokenLatch> released = allLatchesBut(world, mover, pivot);
  const std::array<geometry::Cell, 1> place = {geometry::Cell{2, 2, 1}};
  const Mover hanging{mover, pivot, place, {}};
  LoadJudge judge(LoadParameters{});
  EXPECT_FALSE(judge.judge(world, {released, {}, hanging}).has_value());
  EXPECT_EQ(judge.counts().solves, 1u);
  // The mover and the few floor modules it was latched to.
  EXPECT_GE(judge.counts().largest, 2u);
  EXPECT_LE(judge.counts().largest, 7u);
}

TEST(CheckAtRest, RefusesAnOverloadedSceneNamingTheLatchAndAcceptsItsStrongerTwin) {
  const world::World world = footedCantilever(3, 4);
  const Weakest weakest = weakestOf(world, {});
  const Status overloaded = checkAtRest(world, scaledSoThat(weakest.safety, 0.999));
  ASSERT_FALSE(overloaded.ok());
  EXPECT_NE(overloaded.error().find(latchName(weakest) + "carries"), std::string::npos)
      << overloaded.error();
  EXPECT_TRUE(checkAtRest(world, scaledSoThat(weakest.safety, 1.001)).ok());
}

}  // namespace
}  // namespace datomsim::mechanics
