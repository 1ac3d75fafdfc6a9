// The simulator under a message-heavy load: the distributed gradient on flat boxes.
//
// Reports events per second (event loop alone, and whole run) and the simulator's bytes per module
// (world and simulator state, without the program objects).
#include <benchmark/benchmark.h>

#include "algorithms/gradient.h"
#include "experiment/run.h"
#include "scene/box.h"
#include "sim/simulator.h"

namespace datomsim {
namespace {

void gradientOnBox(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const world::World world = *scene::box({side, side, 2});
  const motion::RuleTable table;
  experiment::RunRequest request;
  request.goal = {side / 2, side / 2, 2};
  uint64_t events = 0, messages = 0;
  double runSeconds = 0;
  for (auto _ : state) {
    const auto run = experiment::runProgram(world, table, request);
    events += run->statistics.events();
    messages += run->statistics.messages();
    runSeconds += run->statistics.wallSeconds;
  }
  state.counters["modules"] = double(world.size());
  // Events per second of the event loop alone (Simulator::run), and of the whole run with its
  // set-up (copying the world, making 1 program per module, gathering the distances).
  state.counters["loop_events/s"] = double(events) / runSeconds;
  state.counters["events/s"] = benchmark::Counter(double(events), benchmark::Counter::kIsRate);
  state.counters["events"] = double(events) / double(state.iterations());
  state.counters["messages"] = double(messages) / double(state.iterations());
  state.counters["program_bytes/module"] = double(sizeof(algorithms::GradientProgram));
  state.counters["idle_bytes/module"] = double(world.memoryBytes()) / double(world.size()) +
                                        double(sim::Simulator::bytesPerModuleState());
}

BENCHMARK(gradientOnBox)->Name("Small/Gradient")->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(gradientOnBox)
    ->Name("Gradient")
    ->Arg(70)
    ->Arg(224)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
}  // namespace datomsim

BENCHMARK_MAIN();
