// Reachability (motion::reach) on flat boxes of 10 thousand to 2 million modules, goal on top,
// on one thread and on two (the same map: the second argument is the threads).
//
// Reports rule evaluations per second and the bytes held by the world and the distance map.
// Peak memory of the whole process: /usr/bin/time -v build/release/bench/motion_bench
// --benchmark_filter=Reach/1000 (see the issue notes and docs/motion-rules.md).
#include <benchmark/benchmark.h>

#include "motion/reach.h"
#include "scene/box.h"

namespace datomsim {
namespace {

void reachOnBox(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  const world::World world = *scene::box({side, side, 2});
  const motion::RuleTable table;
  const geometry::Cell goal{side / 2, side / 2, 2};
  uint64_t evaluations = 0;
  size_t cells = 0, mapBytes = 0;
  for (auto _ : state) {
    const auto map = motion::reach(world, table, goal, {}, threads);
    evaluations += map->ruleEvaluations();
    cells = map->size();
    mapBytes = map->memoryBytes();
    benchmark::DoNotOptimize(cells);
  }
  state.counters["modules"] = double(world.size());
  state.counters["reachable"] = double(cells);
  state.counters["rules/s"] = benchmark::Counter(double(evaluations), benchmark::Counter::kIsRate);
  state.counters["world_MB"] = double(world.memoryBytes()) / 1e6;
  state.counters["map_MB"] = double(mapBytes) / 1e6;
}

// Small cases run in CI's smoke run; the rest on demand (scripts/bench.sh).
BENCHMARK(reachOnBox)->Name("Small/Reach")->Args({70, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(reachOnBox)
    ->Name("Reach")
    ->ArgsProduct({{70, 224, 707, 1000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

}  // namespace
}  // namespace datomsim

BENCHMARK_MAIN();
