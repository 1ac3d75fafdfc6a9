// The subcommands of `datomsim`, and what they share: turning errors into messages and writing
// outputs whole or not at all.
#pragma once

#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "algorithms/registry.h"
#include "arguments.h"
#include "datomsim/program.h"
#include "datomsim/result.h"
#include "experiment/run.h"
#include "geometry/cell.h"
#include "io/scene.h"
#include "motion/reach.h"
#include "video/recorder.h"
#include "world/world.h"

namespace datomsim::app {

void addGeometryCommand(CLI::App& app);
void addSceneCommands(CLI::App& app);  // generate, convert, info
// generate reshape CASE: the reconfiguration cases.
void addReshapeGenerator(CLI::App& generate);
void addMotionCommands(CLI::App& app);  // reach, moves, verify
void addCompareCommand(CLI::App& app);  // the Datom and the 3D Catom on one scene
// `run`, with the programs a researcher's executable adds (they outlive the command line).
void addRunCommand(CLI::App& app, std::span<const ProgramEntry> added = {});
void addDemoCommand(CLI::App& app);
void addViewCommand(CLI::App& app);
void addMeshCommand(CLI::App& app);
void addVideoCommand(CLI::App& app);
void addSweepCommand(CLI::App& app);

// What `run` takes, as the command line spells it (cells "x,y,z", parameters "KEY=VALUE"); the
// Python package fills the same from its keywords.
struct RunArguments {
  std::string scene, program, goal, start, out, trace, target, root;
  std::vector<std::string> parameters;
  double timeoutS = 0, untilS = 0;
  bool stats = false;
  RuleArguments rules;
  // The modules' kind (empty: the scene's) and the 3D Catom's rule set (docs/catom3d.md).
  std::string module;
  std::string rolling = "symmetric";
  std::string seed = "1";
  double delayMs = 10, jitterMs = 0;
  int maxMotions = 0;
  // --connectivity was given (reconfiguration keeps the ensemble connected unless told).
  bool connectivityGiven = false;
  // Record the trace even with no --trace file (the caller writes it).
  bool wantTrace = false;
};

// A run and what its JSON is made of (runJson); `failure` says why it did not do what it was
// asked (the target not built, the mobile stuck, an invariant violated), when it did not.
struct RunOutput {
  algorithms::ProgramInfo info;
  experiment::RunResult result;
  std::map<std::string, std::string> parameters;
  std::optional<std::string> failure;
};

// `run` on a scene in memory (`sceneName` goes into the description): the checks and the
// messages of the command line, which throws UsageError where `run` would refuse. A run that
// fails is a result with its failure, not an error.
RunOutput runOnScene(io::Scene scene, const std::string& sceneName, const RunArguments& args,
                     std::span<const ProgramEntry> added = {});

// `reach` on a scene in memory: the mobile chosen and taken out as `run` does, the goal checked
// (inside the world, next to a module), the distances and, with a start, the path.
struct ReachOutput {
  world::World fixed;  // the scene without the mobile
  bool mobileTakenOut = false;
  motion::DistanceMap map;
  std::vector<geometry::Cell> path;
};
// The scene's own module kind with the Datom's rule options (what the Python package asks),
// or any motion model.
ReachOutput reachOnScene(io::Scene scene, const geometry::Cell& goal,
                         const std::optional<geometry::Cell>& start,
                         const motion::RuleOptions& options);
ReachOutput reachOnScene(io::Scene scene, const geometry::Cell& goal,
                         const std::optional<geometry::Cell>& start, const MotionModel& model);

// What `geometry --json` prints: a Datom's dimensions from r and t, and with a compression
// fraction its joint angles.
nlohmann::ordered_json geometryJson(double radius, double thickness,
                                    const std::optional<double>& fraction);

// What `generate reshape CASE` takes, as the command line spells it.
struct ReshapeArguments {
  std::string kase, out, floor = "12,12";
  int length = 8;
  int modules = 20;
  int side = 96;
  int base = 0;
  std::string seed = "1";
};

// The reconfiguration case `generate reshape` writes: its scene, whose first target is the shape
// to build (docs/reconfiguration.md).
io::Scene reshapeCase(const ReshapeArguments& args);

// For `video` and `demo`: a count of frames on standard error when it is a terminal (none with
// --quiet or in a log), and what a video holds for its "wrote" line.
std::function<void(int, int)> videoProgress(const std::string& name);
std::string describeVideo(const video::VideoSummary& made, const video::VideoRequest& request);
// `completion bash|zsh`, from the whole command line `app` (add it last).
void addCompletionCommand(CLI::App& app);

// Ends a subcommand's --help with one example of its use, run from the repository's root (the
// test CommandLine.EverySubcommandsHelpEndsWithAnExampleThatRuns runs each).
void addExample(CLI::App& command, const std::string& arguments);

// A check that ran and found a problem (e.g. counterexamples); exit status 1.
class CheckFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The value of a result, or a UsageError carrying its message.
template <typename T>
T unwrap(Result<T>&& result) {
  if (!result.ok()) throw UsageError(result.error());
  return std::move(result).value();
}
void check(const Status& status);

// The JSON result of `run` (see docs/file-formats.md).
std::string runJson(const algorithms::ProgramInfo& program, const experiment::RunResult& result,
                    const std::map<std::string, std::string>& parameters = {});
// The same, streamed to an open file (a large scene's lists are not held as one text).
Status writeRunJson(const algorithms::ProgramInfo& program, const experiment::RunResult& result,
                    const std::map<std::string, std::string>& parameters, std::FILE* file);

// What a command tells a person on standard error besides errors: "wrote PATH" for every file it
// writes (every command, every file, and none it does not write), with what the file holds when
// that helps; and notes, such as a picture drawn smaller than asked. `datomsim --quiet`
// silences both; errors and warnings of failure are always said.
void setQuiet(bool quiet);
bool quiet();
void reportWritten(const std::string& path, std::string_view holds = {});
void note(std::string_view line);

// Writes text to a file atomically, or to standard output when the path is empty or "-"; a file
// is reported (reportWritten).
void writeOutput(const std::string& path, const std::string& text);
// The same for text written as it is made, by `write` on an open file.
void writeOutput(const std::string& path, const std::function<Status(std::FILE*)>& write);

// A file a command reads or writes, with the option that names it ("scene", "--out"). An output
// path that is empty or "-" is standard output.
struct NamedPath {
  std::string option;
  std::string path;
};

// Refuses, before anything is read or written, outputs that would overwrite an input, two
// outputs naming the same file, and two outputs both on standard output.
void refuseClashes(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

// The --out option whose value writeOutput takes.
void addOutputOption(CLI::App& command, std::string& out);

// VisibleSim opens only a file that declares its grid: a scene about to be written as XML (`out`'s
// extension says) without one gets the smallest grid that holds its modules and its grid targets
// with room to move, and a note says so. Refuses a scene with cells before the grid's origin.
void declareGridForVisibleSim(io::Scene& scene, const std::string& out);
// The same modules (ids, orientations, colours, order) moved by `offset` into a world of
// `bounds`, all neighbours latched.
world::World rebuilt(const world::World& from, const world::Bounds& bounds,
                     const geometry::Cell& offset);
// The smallest and largest grid coordinates (x + floor(z/2), y + floor(z/2), z) of the modules.
std::pair<geometry::Cell, geometry::Cell> gridExtent(const world::World& world);

// The distance map pictures asked for: their files (none when empty) and their size.
struct PictureRequest {
  std::string png;
  std::string svg;
  // Pixels per cell; 0 for the default, 48.
  int scale = 0;
  // The longest side in pixels, 0 for no limit, -1 for the default: 4000 pixels without a
  // scale (the default scale is lowered to fit), no limit with one.
  int maxSize = -1;
  // "paper", "continuous", or "auto" (the paper's colours below distance 25).
  std::string palette = "auto";
};

// The distance map pictures, for each file asked for. `world` holds the fixed modules; the
// mobile, when it was taken out of the scene, is counted in the title. Says on standard error
// when the pictures are drawn smaller than asked or without some of their numbers.
void writePictures(const world::World& world, bool mobileTakenOut, const motion::DistanceMap& map,
                   const std::vector<geometry::Cell>& path, const std::string& title,
                   const PictureRequest& request);

}  // namespace datomsim::app
