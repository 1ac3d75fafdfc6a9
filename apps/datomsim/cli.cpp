// The command line as a function: `datomsim` calls it with the built-in programs, a researcher's
// executable with its own programs added (datomsim/main.h).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>

#include "algorithms/registry.h"
#include "commands.h"
#include "datomsim/main.h"

namespace datomsim {

int main(int argc, char** argv, std::vector<ProgramEntry> programs) {
  if (const Status names = algorithms::checkAdded(programs); !names.ok()) {
    fmt::print(stderr, "datomsim: error: {}\n", names.error());
    return 1;
  }
  CLI::App app{
      "datomsim: a simulator for Datoms, deformable modular robots in the FCC lattice.\n"
      "Run `datomsim SUBCOMMAND --help` for the options of each subcommand."};
  // Help and errors name the executable as the user called it.
  app.name(argc > 0 && argv[0] ? std::filesystem::path(argv[0]).filename().string() : "datomsim");
  app.require_subcommand(1);
  app.set_version_flag("--version", "datomsim 0.1.0");
  app::addGeometryCommand(app);
  app::addSceneCommands(app);
  app::addMotionCommands(app);
  app::addRunCommand(app, programs);
  app::addDemoCommand(app);
  app::addViewCommand(app);
  app::addMeshCommand(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  } catch (const app::UsageError& error) {
    fmt::print(stderr, "datomsim: error: {}\n", error.what());
    return 1;
  } catch (const app::CheckFailed& error) {
    fmt::print(stderr, "datomsim: {}\n", error.what());
    return 1;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "datomsim: error: out of memory\n");
    return 1;
  } catch (const std::exception& error) {
    // A researcher's program that throws (a parameter it did not declare, say) ends the run
    // with its message rather than an abort.
    fmt::print(stderr, "datomsim: error: {}\n", error.what());
    return 1;
  }
  return 0;
}

}  // namespace datomsim
