// The load model on large scenes: building the model of a box of modules and solving it (sparse
// assembly, then the conjugate gradient above mechanics::kDirectLimit free modules), as
// `datomsim loads` does. The goal: a million modules in under 30 s and 4 GB on one core.
//
// Reports the modules, the solver's iterations, the bytes its matrix and vectors hold, and the
// process's peak resident memory (VmHWM: the world and the model included).
#include <benchmark/benchmark.h>

#include <fstream>
#include <string>

#include "mechanics/load_model.h"
#include "mechanics/load_solver.h"
#include "scene/box.h"

namespace datomsim {
namespace {

// The peak resident memory of the process so far, in bytes (Linux's VmHWM), or 0.
double peakResidentBytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) * 1024.0;
  }
  return 0;
}

// A box of X x Y x Z modules, upright, on the ground: its lowest layer held.
void loadsOnBox(benchmark::State& state) {
  scene::BoxOptions options;
  options.upright = true;
  const geometry::Cell size{int(state.range(0)), int(state.range(1)), int(state.range(2))};
  const world::World world = *scene::box(size, options);
  mechanics::LoadSolution last;
  for (auto _ : state) {
    const mechanics::LoadModel model = *mechanics::buildLoadModel(world, {});
    Result<mechanics::LoadSolution> solution = mechanics::solveLoads(model);
    if (!solution) {
      state.SkipWithError(solution.error().c_str());
      return;
    }
    last = std::move(*solution);
  }
  state.counters["modules"] = double(world.size());
  state.counters["iterations"] = last.iterations;
  state.counters["solver_MB"] = double(last.memoryBytes) / 1e6;
  state.counters["peak_rss_MB"] = peakResidentBytes() / 1e6;
}

// Small: factorised (under the direct limit). Large: iterative; the last is the million.
BENCHMARK(loadsOnBox)->Name("LoadsOnBoxSmall")->Args({10, 10, 4})->Unit(benchmark::kMillisecond);
BENCHMARK(loadsOnBox)
    ->Name("LoadsOnBox")
    ->Args({100, 100, 10})
    ->Args({500, 500, 4})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
}  // namespace datomsim

BENCHMARK_MAIN();
