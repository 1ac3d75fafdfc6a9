// Reachability (motion::reach) on flat boxes of 10 thousand to 2 million modules, goal on top.
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
  const world::World world = *scene::box({side, side, 2});
  const motion::RuleTable table;
  const geometry::Cell goal{side / 2, side / 2, 2};
  uint64_t evaluations = 0;
  size_t cells = 0, mapBytes = 0;
  for (auto _ : state) {
    const auto map = motion::reach(world, table, goal, {});
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
BENCHMARK(reachOnBox)->Name("Small/Reach")->Arg(70)->Unit(benchmark::kMillisecond);
BENCHMARK(reachOnBox)
    ->Name("Reach")
    ->Arg(70)
    ->Arg(224)
    ->Arg(707)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
}  // namespace datomsim

BENCHMARK_MAIN();
