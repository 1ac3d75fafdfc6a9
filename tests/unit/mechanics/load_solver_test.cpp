// The load model against closed forms: a cantilever's root moment and deflection, a column's
// axial loads, the weight carried across every layer of a box, a symmetric arch.
#include "mechanics/load_solver.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mechanics/load_model.h"
#include "scene/box.h"
#include "unit/mechanics/mechanics_scenes.h"

namespace datomsim::mechanics {
namespace {

using elastic::LatchLoad;
using elastic::LoadParameters;

using testing::beamBetween;
using testing::nodeOf;

struct Solved {
  LoadModel model;
  LoadSolution solution;
};

Solved solve(const world::World& world, LoadParameters parameters = {},
             SolverOptions options = {}) {
  Result<LoadModel> model = buildLoadModel(world, parameters);
  EXPECT_TRUE(model.ok()) << model.error();
  Result<LoadSolution> solution = solveLoads(*model, options);
  EXPECT_TRUE(solution.ok()) << solution.error();
  return {std::move(*model), std::move(*solution)};
}

double weightOfOne(const LoadModel& model) {
  return model.moduleMass * geometry::norm(model.parameters.gravity);
}

TEST(Cantilever, RootLatchMomentIsTheWeightsTimesTheirLeverArmsAndGrowsAsTheSquareOfTheLength) {
  double firstMoment = 0;
  for (int arm = 1; arm <= 6; ++arm) {
    const Solved solved = solve(testing::cantilever(3, arm));
    // The root latch joins the column's top (id 3) and the arm's first module (id 4), half a
    // beam from each; module k of the arm hangs (k - 1/2) L beyond it, L = 2r.
    const int root = beamBetween(solved.model, ModuleId{3}, ModuleId{4});
    ASSERT_GE(root, 0);
    const LatchLoad& load = solved.solution.latches[size_t(root)];
    const double w = weightOfOne(solved.model);
    const double length = solved.model.section.length;
    const double expected = w * length * arm * arm / 2.0;
    EXPECT_NEAR(geometry::norm(load.moment), expected, 1e-9 * expected) << arm;
    EXPECT_NEAR(load.bendingMoment, expected, 1e-9 * expected) << arm;
    EXPECT_NEAR(load.torsion, 0.0, 1e-9 * expected) << arm;
    // The column holds the arm's whole weight up, across the beam.
    EXPECT_NEAR(load.force.z, arm * w, 1e-9 * arm * w) << arm;
    EXPECT_NEAR(load.shearForce, arm * w, 1e-9 * arm * w) << arm;
    EXPECT_NEAR(load.axialForce, 0.0, 1e-9 * arm * w) << arm;
    if (arm == 1) firstMoment = geometry::norm(load.moment);
    EXPECT_NEAR(geometry::norm(load.moment) / firstMoment, double(arm * arm), 1e-9) << arm;
  }
}

TEST(Cantilever, DeflectionIsTheEulerBernoulliBeamsUnderItsNodalWeights) {
  const int arm = 5;
  const Solved solved = solve(testing::cantilever(3, arm));
  const LoadModel& model = solved.model;
  // The arm bends as a beam clamped at the column's top: take away that node's rigid motion.
  const size_t root = size_t(nodeOf(model, ModuleId{3}));
  const size_t tip = size_t(nodeOf(model, ModuleId{3 + arm}));
  const geometry::Vec3 lever = model.nodes[tip].position - model.nodes[root].position;
  const geometry::Vec3 rigid =
      solved.solution.displacement[root] + geometry::cross(solved.solution.rotation[root], lever);
  const double deflection = solved.solution.displacement[tip].z - rigid.z;
  // Point loads P at x_k = k L: the tip of a cantilever of length n L goes down by
  // sum P x_k^2 (3 n L - x_k) / (6 E I).
  const double w = weightOfOne(model);
  const double length = model.section.length;
  const double ei = model.parameters.youngModulus * model.section.inertia;
  double expected = 0;
  for (int k = 1; k <= arm; ++k) {
    const double x = k * length;
    expected += w * x * x * (3 * arm * length - x) / (6 * ei);
  }
  EXPECT_NEAR(-deflection, expected, 1e-6 * expected);
  EXPECT_GT(expected, 0);
}

TEST(Column, EachLatchCarriesTheWeightAboveIt) {
  const int height = 8;
  const Solved solved = solve(testing::zigzagColumn(height));
  const double w = weightOfOne(solved.model);
  for (int z = 0; z + 1 < height; ++z) {
    const int beam =
        beamBetween(solved.model, ModuleId{uint32_t(z + 1)}, ModuleId{uint32_t(z + 2)});
    ASSERT_GE(beam, 0) << z;
    const LatchLoad& load = solved.solution.latches[size_t(beam)];
    const double above = (height - 1 - z) * w;
    // Straight up, and nothing else.
    EXPECT_NEAR(load.force.z, above, 1e-9 * above) << z;
    EXPECT_NEAR(std::hypot(load.force.x, load.force.y), 0.0, 1e-9 * above) << z;
    // Along a beam leaning 45 degrees from the vertical (the lattice's up-neighbours).
    EXPECT_NEAR(-load.axialForce, above * std::sqrt(0.5), 1e-9 * above) << z;
  }
  EXPECT_NEAR(solved.solution.totalWeight, height * w, 1e-12);
}

TEST(Box, TheLatchesAcrossEachLayerCarryTheWeightOfTheLayersAbove) {
  scene::BoxOptions options;
  options.upright = true;
  const world::World world = *scene::box({4, 3, 5}, options);
  const Solved solved = solve(world);
  const double w = weightOfOne(solved.model);
  for (int layer = 0; layer < 4; ++layer) {
    double carried = 0;
    for (size_t k = 0; k < solved.model.beams.size(); ++k) {
      const Beam& beam = solved.model.beams[k];
      const int za = solved.model.nodes[beam.a].cell.z, zb = solved.model.nodes[beam.b].cell.z;
      // The force the lower module puts on the upper one.
      const double up = solved.solution.latches[k].force.z;
      if (za == layer && zb == layer + 1) carried += up;
      if (zb == layer && za == layer + 1) carried -= up;
    }
    const double above = (4 - layer) * 12 * w;
    EXPECT_NEAR(carried, above, 1e-8 * above) << layer;
  }
}

TEST(Arch, BothSidesCarryTheSameLoads) {
  const int height = 4, k = 6;
  const Solved solved = solve(testing::symmetricArch(height, k));
  const LoadModel& model = solved.model;
  size_t compared = 0;
  for (size_t b = 0; b < model.beams.size(); ++b) {
    const geometry::Cell a1 = model.nodes[model.beams[b].a].cell;
    const geometry::Cell b1 = model.nodes[model.beams[b].b].cell;
    // The mirrored latch.
    for (size_t m = 0; m < model.beams.size(); ++m) {
      const geometry::Cell a2 = model.nodes[model.beams[m].a].cell;
      const geometry::Cell b2 = model.nodes[model.beams[m].b].cell;
      const bool same = (a2 == testing::mirrored(a1, k) && b2 == testing::mirrored(b1, k)) ||
                        (a2 == testing::mirrored(b1, k) && b2 == testing::mirrored(a1, k));
      if (!same) continue;
      const LatchLoad& one = solved.solution.latches[b];
      const LatchLoad& other = solved.solution.latches[m];
      const double scale = geometry::norm(one.force) + 1e-12;
      EXPECT_NEAR(geometry::norm(one.force), geometry::norm(other.force), 1e-9 * scale);
      EXPECT_NEAR(geometry::norm(one.moment), geometry::norm(other.moment),
                  1e-9 * (geometry::norm(one.moment) + 1e-12));
      ++compared;
    }
  }
  EXPECT_EQ(compared, model.beams.size());
  // The two feet hold half the weight each, straight up.
  const double half = solved.solution.totalWeight / 2;
  for (const geometry::Cell foot : {geometry::Cell{0, 0, 0}, geometry::Cell{k, 0, 0}}) {
    double up = 0;
    for (size_t b = 0; b < model.beams.size(); ++b) {
      const Beam& beam = model.beams[b];
      if (model.nodes[beam.a].cell == foot) up += solved.solution.latches[b].force.z;
      if (model.nodes[beam.b].cell == foot) up -= solved.solution.latches[b].force.z;
    }
    EXPECT_NEAR(up, half - weightOfOne(model), 1e-9 * half) << foot;
  }
}

TEST(Solver, TheIterativeSolverAgreesWithTheFactorisation) {
  const world::World world = *scene::box({5, 4, 4});
  SolverOptions direct;
  direct.method = SolverMethod::kDirect;
  SolverOptions iterative;
  iterative.method = SolverMethod::kIterative;
  const Solved exact = solve(world, {}, direct);
  const Solved approximate = solve(world, {}, iterative);
  EXPECT_EQ(exact.solution.method, "sparse LDLT");
  EXPECT_EQ(approximate.solution.method, "conjugate gradient");
  EXPECT_GT(approximate.solution.iterations, 0);
  EXPECT_LT(exact.solution.residual, 1e-12);
  EXPECT_LT(approximate.solution.residual, 1e-9);
  for (size_t k = 0; k < exact.model.beams.size(); ++k) {
    const double scale = geometry::norm(exact.solution.latches[k].force) + 1e-3;
    EXPECT_NEAR(geometry::norm(approximate.solution.latches[k].force),
                geometry::norm(exact.solution.latches[k].force), 1e-6 * scale);
  }
}

TEST(Solver, AWorldAllOnTheGroundHasNothingToSolve) {
  const Solved solved = solve(*scene::box({3, 3, 1}));
  for (const LatchLoad& load : solved.solution.latches) {
    EXPECT_EQ(geometry::norm(load.force), 0.0);
    EXPECT_TRUE(std::isinf(load.safety));
  }
}

}  // namespace
}  // namespace datomsim::mechanics
