// The built-in flood program (written against the public API) gives every module its hop count
// from the root: a centralised breadth-first search over the same latches gives the same.
#include <gtest/gtest.h>

#include <deque>
#include <map>

#include "algorithms/registry.h"
#include "experiment/run.h"
#include "geometry/lattice.h"
#include "scene/box.h"
#include "scene/random_scene.h"
#include "support/rule_table.h"

namespace datomsim {
namespace {

// Hop counts by breadth-first search from the root over latched neighbours.
std::map<Cell, int> breadthFirst(const world::World& world, const Cell& root) {
  std::map<Cell, int> hops{{root, 0}};
  std::deque<Cell> queue{root};
  while (!queue.empty()) {
    const Cell cell = queue.front();
    queue.pop_front();
    const world::Module& module = *world.moduleAt(cell);
    for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
      const world::Module* next = world.neighbour(module, direction);
      if (!next || !world.isLatched(module, direction) || hops.count(next->cell)) continue;
      hops[next->cell] = hops[cell] + 1;
      queue.push_back(next->cell);
    }
  }
  return hops;
}

std::map<Cell, int> flood(world::World world, const Cell& root, Time jitter) {
  experiment::RunRequest request;
  request.program = "flood";
  request.parameters = {{"root", toString(root)}};
  request.simulation.messageJitter = jitter;
  const auto run = experiment::runProgram(std::move(world), testing::paperRules(), request);
  EXPECT_TRUE(run.ok()) << run.error();
  if (run.ok()) {
    EXPECT_FALSE(run->failure) << *run->failure;
  }
  std::map<Cell, int> hops;
  if (!run.ok()) return hops;
  // The parameters as given, whether --until stopped the run, then the one key reported.
  std::vector<std::string> keys;
  for (const auto& section : run->report.sections()) keys.push_back(section.key);
  EXPECT_EQ(keys, (std::vector<std::string>{"parameters", "stopped_at_limit", "hops"}));
  for (const auto& [cell, value] : run->report.cellValues("hops")) hops[cell] = int(value);
  return hops;
}

TEST(Flood, HopCountsOnBoxesAreTheBreadthFirstSearchs) {
  struct Case {
    Cell size;
    Cell root;
  };
  for (const Case& c :
       {Case{{5, 4, 3}, {0, 0, 0}}, Case{{8, 8, 2}, {3, 5, 1}}, Case{{12, 3, 4}, {11, 2, 0}}}) {
    const auto world = scene::box(c.size);
    ASSERT_TRUE(world.ok()) << world.error();
    const auto expected = breadthFirst(*world, c.root);
    EXPECT_EQ(expected.size(), world->size());
    // Jitter reorders messages: the counts must not depend on which arrives first.
    for (const Time jitter : {Time(0), 25 * kMillisecond}) {
      EXPECT_EQ(flood(*world, c.root, jitter), expected) << c.size << " root " << c.root;
    }
  }
}

TEST(Flood, OnRandomScenesWithRandomOrientationsHopCountsAreTheBreadthFirstSearchs) {
  // Orientations change which own connector faces which neighbour: the count must not.
  scene::RandomOptions options;
  options.randomOrientations = true;
  for (const uint64_t seed : {3u, 4u, 5u}) {
    const auto world = scene::random(seed, 80, options);
    ASSERT_TRUE(world.ok()) << world.error();
    const Cell root = world->modules()[17].cell;
    const auto expected = breadthFirst(*world, root);
    EXPECT_EQ(expected.size(), world->size());
    EXPECT_EQ(flood(*world, root, 10 * kMillisecond), expected) << "seed " << seed;
  }
}

}  // namespace
}  // namespace datomsim
