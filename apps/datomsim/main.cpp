// datomsim: the command line. Each subcommand parses its options and calls the layers in src/;
// errors reach the user as one line naming the file, line or value at fault, with status 1.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>

#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{
      "datomsim: a simulator for Datoms, deformable modular robots in the FCC lattice.\n"
      "Run `datomsim SUBCOMMAND --help` for the options of each subcommand."};
  app.name("datomsim");
  app.require_subcommand(1);
  app.set_version_flag("--version", "datomsim 0.1.0");
  datomsim::app::addGeometryCommand(app);
  datomsim::app::addSceneCommands(app);
  datomsim::app::addMotionCommands(app);
  datomsim::app::addRunCommand(app);
  datomsim::app::addDemoCommand(app);
  datomsim::app::addViewCommand(app);
  datomsim::app::addMeshCommand(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  } catch (const datomsim::app::UsageError& error) {
    fmt::print(stderr, "datomsim: error: {}\n", error.what());
    return 1;
  } catch (const datomsim::app::CheckFailed& error) {
    fmt::print(stderr, "datomsim: {}\n", error.what());
    return 1;
  }
  return 0;
}
