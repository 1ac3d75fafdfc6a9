// `sweep`: the Python package's sweeps (python/datomsim/sweeps.py, docs/python.md) from the
// command line. It runs Debian's python3 on `-m datomsim.sweeps` with the package this binary was
// built with on PYTHONPATH: the sweep needs Python's process pools and Dask, the runs are the same
// C++ code.
#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "arguments.h"
#include "commands.h"
#include "export/viewer_page.h"

namespace datomsim::app {

namespace {

// The folder holding the package `datomsim`: build/<flavour>/python beside bin/, or the installed
// one under the prefix.
std::filesystem::path packageFolder() {
  const std::filesystem::path bin = unwrap(exporting::executableDirectory());
  for (const std::filesystem::path& candidate :
       {bin / ".." / "python", bin / ".." / DATOMSIM_PYTHON_INSTALL_DIR}) {
    std::error_code error;
    if (std::filesystem::exists(candidate / "datomsim" / "sweeps.py", error)) {
      return std::filesystem::weakly_canonical(candidate);
    }
  }
  throw UsageError(fmt::format(
      "sweep needs the Python package, which is not beside this binary (looked in {} and {}): "
      "build it (it needs pybind11-dev and python3-dev: scripts/install-deps.sh), or install it "
      "with cmake --install",
      (bin / ".." / "python").lexically_normal().string(),
      (bin / ".." / DATOMSIM_PYTHON_INSTALL_DIR).lexically_normal().string()));
}

}  // namespace

void addSweepCommand(CLI::App& app, const Reporter& reporter) {
  struct Arguments {
    std::string spec, out, scheduler;
    int workers = 0;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "sweep",
      "Run every combination of a spec's scenes, programs, parameters and seeds, on all cores or "
      "a Dask cluster; one CSV row per run, resumed when stopped (docs/python.md)");
  command->add_option("spec", args->spec, "The sweep's spec, a JSON file")->required();
  command->add_option("-o,--out", args->out, "The results, a .csv file (resumed when it exists)")
      ->required();
  command->add_option("--workers", args->workers, "Processes on this machine (default: every core)")
      ->check(kPositive);
  command->add_option("--scheduler", args->scheduler,
                      "A Dask scheduler's address (tcp://host:8786) to run the cases on");
  addExample(*command, "sweep scenes/sweep-reshape.json -o sweep.csv --workers 2");
  command->callback([args, &reporter] {
    const std::filesystem::path package = packageFolder();
    const char* before = std::getenv("PYTHONPATH");
    const std::string path =
        package.string() + (before != nullptr && *before ? ":" + std::string(before) : "");
    ::setenv("PYTHONPATH", path.c_str(), 1);
    std::vector<std::string> argv = {
        DATOMSIM_PYTHON_EXECUTABLE, "-m", "datomsim.sweeps", args->spec, "-o", args->out};
    if (args->workers > 0) argv.insert(argv.end(), {"--workers", std::to_string(args->workers)});
    if (!args->scheduler.empty()) argv.insert(argv.end(), {"--scheduler", args->scheduler});
    if (reporter.quiet()) argv.push_back("--quiet");
    std::vector<char*> pointers;
    for (std::string& argument : argv) pointers.push_back(argument.data());
    pointers.push_back(nullptr);
    std::fflush(nullptr);
    ::execv(pointers[0], pointers.data());
    throw UsageError(fmt::format("cannot run {}: {}", argv[0], std::strerror(errno)));
  });
}

}  // namespace datomsim::app
