// The subcommands of `datomsim`: each parses its options with CLI11 and calls the services of
// src/frontend (shared with the Python package) and the layers below; what they tell a person
// besides errors goes through the Reporter that `main` sets from --quiet.
#pragma once

#include <functional>
#include <span>
#include <string>

#include <CLI/CLI.hpp>

#include "arguments.h"
#include "datomsim/program.h"
#include "frontend/distance_pictures.h"
#include "frontend/output_file.h"
#include "frontend/reach_on_scene.h"
#include "frontend/reporter.h"
#include "frontend/reshape_case.h"
#include "frontend/run_on_scene.h"
#include "frontend/usage_error.h"
#include "frontend/visiblesim_grid.h"
#include "video/recorder.h"

namespace datomsim::app {

// The services the subcommands are written with, by their own names.
using frontend::check;
using frontend::CheckFailed;
using frontend::CommandFiles;
using frontend::declareGridForVisibleSim;
using frontend::gridExtent;
using frontend::NamedPath;
using frontend::PictureRequest;
using frontend::reachOnScene;
using frontend::ReachOutput;
using frontend::rebuilt;
using frontend::Reporter;
using frontend::ReshapeArguments;
using frontend::reshapeCase;
using frontend::RunArguments;
using frontend::runOnScene;
using frontend::RunOutput;
using frontend::unwrap;
using frontend::writePictures;

// Each subcommand's callback reports through `reporter`, which must outlive the command line;
// `main` sets its quietness once the whole line is parsed, before any callback runs.
void addGeometryCommand(CLI::App& app);
void addSceneCommands(CLI::App& app, const Reporter& reporter);  // generate, convert, info
// generate reshape CASE: the reconfiguration cases.
void addReshapeGenerator(CLI::App& generate, const Reporter& reporter);
void addMotionCommands(CLI::App& app, const Reporter& reporter);  // reach, moves, verify
// The Datom and the 3D Catom on one scene.
void addCompareCommand(CLI::App& app, const Reporter& reporter);
// `run`, with the programs a researcher's executable adds (they outlive the command line).
void addRunCommand(CLI::App& app, const Reporter& reporter,
                   std::span<const ProgramEntry> added = {});
void addDemoCommand(CLI::App& app, const Reporter& reporter);
// The centralised planner of a reconfiguration.
void addPlanCommand(CLI::App& app, const Reporter& reporter);
// The loads on every latch under gravity (docs/mechanics.md).
void addLoadsCommand(CLI::App& app, const Reporter& reporter);
void addViewCommand(CLI::App& app, const Reporter& reporter);
void addMeshCommand(CLI::App& app, const Reporter& reporter);
void addVideoCommand(CLI::App& app, const Reporter& reporter);
void addSweepCommand(CLI::App& app, const Reporter& reporter);
// `actuators show`: designs and their scaling laws (docs/actuators.md).
void addActuatorsCommand(CLI::App& app, const Reporter& reporter);

// For `video` and `demo`: a count of frames on standard error when it is a terminal (none when
// quiet or in a log), and what a video holds for its "wrote" line.
std::function<void(int, int)> videoProgress(const std::string& name, const Reporter& reporter);
std::string describeVideo(const video::VideoSummary& made, const video::VideoRequest& request);
// `completion bash|zsh`, from the whole command line `app` (add it last).
void addCompletionCommand(CLI::App& app);
void addStudioCommand(CLI::App& app);  // studio

// Ends a subcommand's --help with one example of its use, run from the repository's root (the
// test CommandLine.EverySubcommandsHelpEndsWithAnExampleThatRuns runs each).
void addExample(CLI::App& command, const std::string& arguments);

// The --out option: a file, or standard output when it is "-" or not given (CommandFiles).
void addOutputOption(CLI::App& command, std::string& out);

}  // namespace datomsim::app
