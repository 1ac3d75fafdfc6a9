// The simulator under load: the distributed gradient on flat boxes (message-heavy), and the
// self-reconfiguration of a floor's corner block into a pyramid (many motions at once).
//
// Reports events per second (event loop alone, and whole run) and the simulator's bytes per module
// (world and simulator state, without the program objects); for reconfiguration, what the run
// built and how long it took, simulated and on the wall.
#include <benchmark/benchmark.h>

#include "algorithms/gradient.h"
#include "algorithms/registry.h"
#include "experiment/run.h"
#include "scene/box.h"
#include "scene/reshape.h"
#include "sim/simulator.h"

namespace datomsim {
namespace {

void gradientOnBox(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const world::World world = *scene::box({side, side, 2});
  const motion::RuleTable table;
  experiment::RunRequest request;
  request.program = "gradient";
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

// `datomsim run` of `generate reshape pyramid --side S`: the floor's corner block becomes a
// pyramid in its middle, connectivity on, as the command line runs it.
void reshapePyramid(benchmark::State& state) {
  const scene::ReshapeCase reshape = *scene::cornerToPyramid(int(state.range(0)));
  const motion::RuleTable table;
  experiment::RunRequest request;
  request.program = "reconfigure";
  request.targets = {reshape.target};
  request.simulation.connectivity = true;
  request.simulation.rules.connectivity = true;
  bool built = true;
  uint64_t events = 0, motions = 0;
  double makespan = 0;
  for (auto _ : state) {
    const auto run = experiment::runProgram(reshape.world, table, request);
    built = built && run.ok() && run->reshape && run->reshape->success;
    events += run->statistics.events();
    motions += run->statistics.motions;
    makespan += double(run->statistics.lastMotionEnd) / kSecond;
  }
  const auto iterations = double(state.iterations());
  state.counters["modules"] = double(reshape.world.size());
  state.counters["built"] = built ? 1 : 0;
  state.counters["motions"] = double(motions) / iterations;
  state.counters["makespan_s"] = makespan / iterations;
  state.counters["events/s"] = benchmark::Counter(double(events), benchmark::Counter::kIsRate);
}

BENCHMARK(reshapePyramid)->Name("Small/ReshapePyramid")->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK(reshapePyramid)
    ->Name("ReshapePyramid")
    ->Arg(64)
    ->Arg(100)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
}  // namespace datomsim

BENCHMARK_MAIN();
