// A motion is judged again when it starts, after its helpers compressed their pistons: judged as
// when it was chosen, not on the latches those compressions let go. The program's motion, listed
// before, is taken back by its rule and helpers, not listed again (a fresh list refuses it).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <vector>

#include "geometry/lattice.h"
#include "scene/random_scene.h"
#include "sim/simulator.h"
#include "support/scripted_program.h"

namespace datomsim::sim {
namespace {

using testing::Script;
using testing::scripts;

// Random scene 1 (60 modules, random orientations) holds a motion of module 32, by rule 24
// about module 20, whose helper 50 must compress world axis 1, then axis 5 (a double
// deformation), and helper 21 axis 4. Module 50 holds to the ensemble away from axis 5 only
// through its latch to module 54, which its first piston (axis 1) lets go. Judged on the latches
// after the compressions, the rule refused the motion at its start ("module 50 cannot compress
// piston 5: it is latched only through connectors that piston moves"); the latch is back before
// axis 5 compresses, half-way through the motion.
TEST(MotionStart, IsJudgedAsBeforeItsHelpersDeformed) {
  const motion::RuleTable table;
  scene::RandomOptions options;
  options.randomOrientations = true;
  auto world = scene::random(1, 60, options);
  ASSERT_TRUE(world.ok()) << world.error();
  const world::Module& mover = *world->find(ModuleId{32});
  std::optional<motion::Motion> chosen;
  for (motion::Motion& motion : motion::validMotions(*world, table, {mover.cell, mover.id}, {})) {
    if (motion.rule == 24 && motion.pivot == ModuleId{20}) chosen = std::move(motion);
  }
  ASSERT_TRUE(chosen.has_value()) << "the scene generator changed: find another case";
  ASSERT_EQ(chosen->deformations.size(), 2u);
  ASSERT_EQ(chosen->deformations[0].module, ModuleId{50});
  ASSERT_EQ(chosen->deformations[0].firstAxis, 1);
  ASSERT_EQ(chosen->deformations[0].secondAxis, 5);

  // The helpers compress a moment after the start, once the mobile has listed its motions.
  std::map<uint32_t, Script> programs;
  for (const motion::Deformation& helper : chosen->deformations) {
    programs[helper.module.value].start = [](Context& c) { c.setTimer(kMillisecond, 0); };
    programs[helper.module.value].timer = [axis = helper.firstAxis](Context& c, int) {
      ASSERT_TRUE(c.compress(c.pistonAlong(axis)).ok());
    };
  }
  const auto isChosen = [](const Motion& m) { return m.rule == 24 && m.pivot == ModuleId{20}; };
  std::optional<Motion> listed;
  bool listedAgain = true;
  std::optional<MoveResult> asked;
  bool arrived = false;
  programs[32].start = [&](Context& c) {
    for (const Motion& m : c.motions()) {
      if (isChosen(m)) listed = m;
    }
    c.setTimer(600 * kMillisecond, 0);
  };
  programs[32].timer = [&](Context& c, int) {
    const std::vector<Motion> fresh = c.motions();
    listedAgain = std::any_of(fresh.begin(), fresh.end(), isChosen);
    ASSERT_TRUE(listed.has_value());
    EXPECT_EQ(listed->helpers.size(), 2u);
    asked = c.move(*listed);
  };
  programs[32].moved = [&](Context&) { arrived = true; };
  Simulator simulator(std::move(*world), table, {});
  simulator.install(scripts(programs));
  simulator.startAll();
  const Status run = simulator.run();

  ASSERT_TRUE(run.ok()) << run.error();  // every invariant held at every event
  EXPECT_FALSE(listedAgain);             // what the simulator must not do: judge on a fresh list
  ASSERT_TRUE(asked.has_value());
  EXPECT_EQ(asked->state(), MoveResult::State::kStarted) << asked->error();
  EXPECT_TRUE(arrived);
  EXPECT_EQ(simulator.world().find(ModuleId{32})->cell, chosen->goal);
}

}  // namespace
}  // namespace datomsim::sim
