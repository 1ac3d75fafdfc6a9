// The load model's refusals (bad parameters, nothing on the ground, modules nothing holds), its
// invariance under a translation and a mirror, the beam element's rigid motions and the tipping
// check.
#include "mechanics/load_model.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "elastic/beam_element.h"
#include "mechanics/load_solver.h"
#include "mechanics/tipping.h"
#include "scene/paper_arch.h"
#include "unit/mechanics/mechanics_scenes.h"

namespace datomsim::mechanics {
namespace {

using elastic::BeamMatrix;
using elastic::BeamSection;
using elastic::beamSection;
using elastic::beamStiffness;
using elastic::BeamVector;
using elastic::LatchLoad;
using elastic::LoadParameters;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string refusal(const world::World& world, const LoadParameters& parameters) {
  const Result<LoadModel> model = buildLoadModel(world, parameters);
  return model.ok() ? std::string("accepted") : model.error();
}

TEST(LoadParameters, RefusesDensityStiffnessAndStrengthThatAreNotPositiveNumbers) {
  const world::World world = testing::zigzagColumn(3);
  struct Case {
    void (*set)(LoadParameters&);
    const char* words;
  };
  const Case cases[] = {
      {[](LoadParameters& p) { p.density = 0; }, "the density must be a positive number"},
      {[](LoadParameters& p) { p.density = -1240; }, "the density must be a positive number"},
      {[](LoadParameters& p) { p.density = kNaN; }, "the density must be a positive number"},
      {[](LoadParameters& p) { p.youngModulus = 0; }, "Young's modulus must be a positive"},
      {[](LoadParameters& p) { p.youngModulus = -3e9; }, "Young's modulus must be a positive"},
      {[](LoadParameters& p) { p.latchForce = 0; }, "the latch force must be a positive"},
      {[](LoadParameters& p) { p.latchMoment = -0.01; }, "the latch moment must be a positive"},
      {[](LoadParameters& p) { p.latchMoment = kNaN; }, "the latch moment must be a positive"},
      {[](LoadParameters& p) { p.solidFraction = 1.5; }, "the solid fraction must be at most 1"},
      {[](LoadParameters& p) { p.poissonRatio = 0.5; }, "Poisson's ratio must lie in (-1, 0.5)"},
      {[](LoadParameters& p) { p.radius = 0; }, "the radius must be a positive number"},
      {[](LoadParameters& p) { p.gravity = {}; }, "gravity must not be zero"},
      {[](LoadParameters& p) { p.gravity.x = kNaN; }, "gravity must be finite"},
  };
  for (const Case& c : cases) {
    LoadParameters parameters;
    c.set(parameters);
    EXPECT_NE(refusal(world, parameters).find(c.words), std::string::npos)
        << c.words << " / " << refusal(world, parameters);
  }
}

TEST(LoadModel, RefusesAnEnsembleThatTouchesNoGround) {
  const world::World world = testing::WorldBuilder().modules({{0, 0, 2}, {1, 0, 2}}).build();
  EXPECT_EQ(refusal(world, {}), "the ensemble touches no ground: nothing holds it");
}

TEST(LoadModel, RefusesAModuleThatNoChainOfLatchesTiesToTheGround) {
  const world::World world = testing::WorldBuilder().modules({{0, 0, 0}, {5, 5, 3}}).build();
  EXPECT_EQ(refusal(world, {}),
            "module 2 at 5,5,3 is tied to the ground by no chain of latches: nothing holds it");
}

TEST(LoadModel, RefusesAModuleWhoseLatchesAreReleased) {
  // Module 3 at (-1,-1,2) hangs from module 2 at (0,0,1), in direction 10 (1,1,-1).
  world::World world = testing::zigzagColumn(3);
  ASSERT_TRUE(world.setLatched(ModuleId{3}, 10, false).ok());
  EXPECT_NE(refusal(world, {}).find("module 3 at "), std::string::npos) << refusal(world, {});
}

TEST(LoadModel, HasANodePerModuleABeamPerLatchAndTheGroundLayerHeld) {
  const Result<LoadModel> model = buildLoadModel(testing::cantilever(3, 4), {});
  ASSERT_TRUE(model.ok()) << model.error();
  EXPECT_EQ(model->nodes.size(), 7u);
  EXPECT_EQ(model->beams.size(), 6u);
  EXPECT_TRUE(model->nodes[0].supported);
  EXPECT_FALSE(model->nodes[1].supported);
  // 1240 kg/m^3 x 0.25 x 4 sqrt2 (1 cm)^3.
  EXPECT_NEAR(model->moduleMass, 1240 * 0.25 * 4 * std::sqrt(2.0) * 1e-6, 1e-15);
  EXPECT_DOUBLE_EQ(model->section.length, 0.02);
}

// The paper's arch, its cells moved by `move`, every latch's load by the ids of its modules.
template <typename Move>
std::map<std::pair<uint32_t, uint32_t>, LatchLoad> archLoads(Move move) {
  const world::World arch = *scene::paperArch(2);
  world::World moved;
  for (const world::Module& module : arch.modules()) {
    world::Module copy = module;
    copy.cell = move(module.cell);
    EXPECT_TRUE(moved.add(copy).ok());
  }
  moved.latchAllNeighbours();
  const LoadModel model = *buildLoadModel(moved, {});
  const LoadSolution solution = *solveLoads(model);
  std::map<std::pair<uint32_t, uint32_t>, LatchLoad> loads;
  for (size_t k = 0; k < model.beams.size(); ++k) {
    uint32_t a = model.nodes[model.beams[k].a].module.value;
    uint32_t b = model.nodes[model.beams[k].b].module.value;
    LatchLoad load = solution.latches[k];
    // Named from the smaller id: the force is then the one that module exerts.
    if (a > b) {
      std::swap(a, b);
      load.force = -load.force;
      load.moment = -load.moment;
    }
    loads[{a, b}] = load;
  }
  return loads;
}

void expectNear(const geometry::Vec3& a, const geometry::Vec3& b, double tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Invariance, TranslatingASceneAlongTheGroundChangesNoLoad) {
  const auto here = archLoads([](const geometry::Cell& c) { return c; });
  const auto there = archLoads([](const geometry::Cell& c) {
    return c + geometry::Cell{7, -4, 0};
  });
  ASSERT_EQ(here.size(), there.size());
  for (const auto& [pair, load] : here) {
    const LatchLoad& moved = there.at(pair);
    expectNear(moved.force, load.force, 1e-12);
    expectNear(moved.moment, load.moment, 1e-14);
  }
}

TEST(Invariance, MirroringASceneMirrorsItsLoads) {
  const auto here = archLoads([](const geometry::Cell& c) { return c; });
  const auto mirror = archLoads([](const geometry::Cell& c) { return testing::mirrored(c, 20); });
  ASSERT_EQ(here.size(), mirror.size());
  for (const auto& [pair, load] : here) {
    const LatchLoad& mirrored = mirror.at(pair);
    // A force is a vector: its x turns over. A moment is an axial vector: its y and z do.
    expectNear(mirrored.force, {-load.force.x, load.force.y, load.force.z}, 1e-12);
    expectNear(mirrored.moment, {load.moment.x, -load.moment.y, -load.moment.z}, 1e-14);
    if (std::isinf(load.safety)) {
      EXPECT_TRUE(std::isinf(mirrored.safety));
    } else {
      EXPECT_NEAR(mirrored.safety, load.safety, 1e-9 * load.safety);
    }
  }
}

TEST(BeamElement, ARigidMotionStrainsNothing) {
  const LoadParameters parameters;
  const BeamSection section = beamSection(parameters);
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const geometry::Vec3 axis =
        geometry::normalized(geometry::worldOffset(geometry::neighbourOffset(d), 1.0));
    const BeamMatrix k = beamStiffness(section, parameters.youngModulus, axis);
    EXPECT_LT((k - k.transpose()).norm(), 1e-9 * k.norm()) << d;
    // A small turn about an axis through end a, and a translation.
    const Eigen::Vector3d turn(0.3e-3, -0.2e-3, 0.5e-3), shift(1e-3, 2e-3, -1e-3);
    const Eigen::Vector3d toB = section.length * Eigen::Vector3d(axis.x, axis.y, axis.z);
    BeamVector ends;
    ends << shift, turn, shift + turn.cross(toB), turn;
    EXPECT_LT((k * ends).norm(), 1e-9 * k.norm() * ends.norm()) << d;
  }
}

TEST(Tipping, ALongArmOnOneFootTips) {
  const LoadModel model = *buildLoadModel(testing::cantilever(3, 6), {});
  const Tipping tipping = checkTipping(model);
  EXPECT_TRUE(tipping.tips);
  EXPECT_LT(tipping.margin, 0);
  EXPECT_NE(tipping.reason.find("outside the support"), std::string::npos);
  // The support is the square of one module's four lower connectors, r on a side.
  EXPECT_EQ(tipping.support.size(), 4u);
}

TEST(Tipping, TheArchStandsAndItsMarginIsTheDistanceToTheSupportsEdge) {
  const LoadModel model = *buildLoadModel(*scene::paperArch(2), {});
  const Tipping tipping = checkTipping(model);
  EXPECT_FALSE(tipping.tips);
  EXPECT_GT(tipping.margin, 0);
  EXPECT_TRUE(tipping.reason.empty());
}

TEST(Tipping, GravityThatDoesNotPointDownTips) {
  LoadParameters sideways;
  sideways.gravity = {9.81, 0, 0};
  const Tipping tipping = checkTipping(*buildLoadModel(testing::zigzagColumn(2), sideways));
  EXPECT_TRUE(tipping.tips);
  EXPECT_NE(tipping.reason.find("does not point down"), std::string::npos);
}

}  // namespace
}  // namespace datomsim::mechanics
