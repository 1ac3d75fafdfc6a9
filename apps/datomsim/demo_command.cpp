// `demo`: the paper's experiment (section VII) on both arch scenes, with its pictures, traces and
// a JSON summary, in one output folder.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "experiment/paper.h"
#include "experiment/run.h"
#include "export/viewer_page.h"
#include "frontend/run_json.h"
#include "io/scene_file.h"
#include "render/distance_map.h"
#include "scene/paper_arch.h"
#include "scene/reshape.h"
#include "video/recorder.h"

namespace datomsim::app {
namespace {

nlohmann::ordered_json cellsJson(const std::vector<geometry::Cell>& cells) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const geometry::Cell& cell : cells) out.push_back({cell.x, cell.y, cell.z});
  return out;
}

}  // namespace

void addDemoCommand(CLI::App& app, const Reporter& reporter) {
  struct Arguments {
    std::string out = "datomsim-demo";
    bool noVideo = false;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "demo", "The paper's experiment on both arch scenes: distance maps, paths, traces, viewers");
  command->add_option("-o,--out", args->out, "Output folder (created if missing)")
      ->capture_default_str();
  command->add_flag("--no-video", args->noVideo,
                    "Skip the videos of the two paper runs (about a minute and a half of drawing "
                    "in headless Chromium)");
  addExample(*command, "demo -o demo-output");
  command->callback([args, &reporter] {
    const std::filesystem::path folder = args->out;
    const auto inFolder = [&](const std::string& name) { return (folder / name).string(); };

    // The viewer's script, if it was built (docs/viewer.md); the rest of the demo does without.
    const auto directory = exporting::executableDirectory();
    const auto bundle = directory.ok() ? exporting::loadViewerBundle("", *directory)
                                       : Result<std::string>(Error{directory.error()});
    if (!bundle.ok()) reporter.note("no viewer pages: " + bundle.error());

    const motion::RuleTable table;
    const experiment::PaperExperiment experiment = unwrap(experiment::runPaperExperiment(table));
    // Every file but the videos checked (and the folder made) before any is written, and all
    // written at the end of the runs, or none; the videos after them.
    std::vector<NamedPath> outputs;
    for (const experiment::PaperScene& result : experiment.scenes) {
      const std::string name = fmt::format("arch-hole{}", result.holeHeight);
      for (const char* suffix : {"-distances.png", "-distances.svg", "-trace.jsonl", "-run.json"}) {
        outputs.push_back({"-o", inFolder(name + suffix)});
      }
      if (bundle.ok()) outputs.push_back({"-o", inFolder(name + "-viewer.html")});
    }
    for (const char* name : {"arch-build-trace.jsonl", "arch-build-run.json"}) {
      outputs.push_back({"-o", inFolder(name)});
    }
    if (bundle.ok()) outputs.push_back({"-o", inFolder("arch-build-viewer.html")});
    outputs.push_back({"-o", inFolder("summary.json")});
    CommandFiles files({}, outputs, folder, "-o");
    nlohmann::ordered_json summary;
    summary["goal"] = cellsJson({scene::kPaperGoal})[0];
    summary["start"] = cellsJson({scene::kPaperStart})[0];
    summary["rules"] = "paper";
    summary["attachment"] = "on";
    nlohmann::ordered_json scenes = nlohmann::ordered_json::array();
    // The viewer pages of the paper's runs, recorded into videos once everything else is written.
    std::vector<std::pair<std::filesystem::path, exporting::ViewerPage>> videos;
    for (const experiment::PaperScene& result : experiment.scenes) {
      const std::string name = fmt::format("arch-hole{}", result.holeHeight);
      const std::string title =
          fmt::format("Paper scene, arch hole {} high: distances to G {} and the path from {}",
                      result.holeHeight, geometry::toString(scene::kPaperGoal),
                      geometry::toString(scene::kPaperStart));
      // The mobile is not among the fixed modules.
      writePictures(
          result.fixedWorld, true, result.distances, result.path, title,
          {.png = inFolder(name + "-distances.png"), .svg = inFolder(name + "-distances.svg")},
          files, reporter);
      files.write(inFolder(name + "-trace.jsonl"), result.run.trace);
      files.write(inFolder(name + "-run.json"),
                  frontend::runJson(experiment::kPaperProgram, result.run));
      if (bundle.ok()) {
        const exporting::ViewerPage page = {
            title, result.run.trace,
            exporting::overlayJson(result.distances.sorted(), result.path, scene::kPaperGoal),
            std::nullopt};
        files.write(inFolder(name + "-viewer.html"), unwrap(exporting::viewerHtml(*bundle, page)));
        videos.emplace_back(folder / (name + "-run.mp4"), page);
      }

      nlohmann::ordered_json entry;
      entry["scene"] = name;
      entry["modules"] = result.fixedWorld.size() + 1;
      entry["reachable_cells"] = result.distances.size();
      entry["max_distance"] = result.distances.maxDistance();
      entry["start_distance"] = *result.distances.distanceAt(scene::kPaperStart);
      entry["path"] = cellsJson(result.path);
      entry["passes_under_arch"] = result.passesUnderArch;
      entry["highest_path_layer"] = result.highestPathLayer;
      entry["simulated_path_matches"] = result.run.report.cells("path") == result.path;
      entry["events"] = result.run.statistics.events();
      entry["messages"] = result.run.statistics.messages();
      entry["sim_time_s"] = double(result.run.statistics.simulatedTime) / kSecond;
      scenes.push_back(std::move(entry));
    }
    summary["scenes"] = std::move(scenes);
    summary["far_side_cells_farther_with_hole1"] = experiment.farSideFartherWithLowHole;

    // Beyond the paper: the arch built by the ensemble itself (docs/reconfiguration.md), with the
    // same run one motion at a time for comparison.
    scene::ReshapeCase build = unwrap(scene::archFromLayer(2));
    experiment::RunRequest request;
    request.program = "reconfigure";
    request.targets = {build.target};
    request.simulation.connectivity = true;
    request.simulation.rules.connectivity = true;
    request.trace = true;
    request.description = "reconfigure: " + build.description;
    const experiment::RunResult built = unwrap(experiment::runProgram(build.world, table, request));
    request.simulation.maxMotions = 1;
    request.trace = false;
    const experiment::RunResult sequential =
        unwrap(experiment::runProgram(std::move(build.world), table, request));
    files.write(inFolder("arch-build-trace.jsonl"), built.trace);
    files.write(inFolder("arch-build-run.json"), frontend::runJson(request.program, built));
    if (bundle.ok()) {
      files.write(inFolder("arch-build-viewer.html"),
                  unwrap(exporting::viewerHtml(
                      *bundle, {request.description, built.trace, "", std::nullopt})));
    }
    const double makespan = double(built.statistics.lastMotionEnd) / kSecond;
    const double baseline = double(sequential.statistics.lastMotionEnd) / kSecond;
    nlohmann::ordered_json arch;
    arch["success"] = built.reshape->success;
    arch["motions"] = built.statistics.motions;
    arch["makespan_s"] = makespan;
    arch["max_concurrent_motions"] = built.statistics.maxConcurrentMotions;
    arch["sequential_makespan_s"] = baseline;
    arch["speed_up"] = makespan > 0 ? baseline / makespan : 0.0;
    summary["arch_build"] = std::move(arch);
    files.write(inFolder("summary.json"), summary.dump(2) + "\n");
    files.commit(reporter);

    // Short videos of the paper's runs, small so that they are quick to draw: 640x360, 12 frames
    // a second, at most 15 s. Without Chromium or ffmpeg the demo says so and does without.
    if (args->noVideo) videos.clear();
    if (const Status tools = video::findVideoTools({}); !videos.empty() && !tools.ok()) {
      reporter.note("no videos: " + tools.error());
      videos.clear();
    }
    for (const auto& [file, page] : videos) {
      video::VideoRequest recording;
      recording.out = file;
      recording.pageHtml = unwrap(exporting::viewerHtml(*bundle, page));
      recording.width = 640;
      recording.height = 360;
      recording.fps = 12;
      recording.longest = 15;
      recording.progress = videoProgress(file.filename().string(), reporter);
      const video::VideoSummary made = unwrap(video::recordVideo(recording));
      reporter.reportWritten(file.string(), describeVideo(made, recording));
    }
    fmt::print("The paper's experiment, files in {}/:\n", args->out);
    for (const experiment::PaperScene& result : experiment.scenes) {
      fmt::print("  arch hole {} high: {} reachable cells, path of {} motions {} the arch\n",
                 result.holeHeight, result.distances.size(), result.path.size() - 1,
                 result.passesUnderArch ? "under" : "over");
    }
    fmt::print(
        "  the arch built by a layer of modules on its box: {} in {} motions, {:.1f} s ({} at "
        "once at most; {:.1f} s one at a time)\n",
        built.reshape->success ? "done" : "not done", built.statistics.motions, makespan,
        built.statistics.maxConcurrentMotions, baseline);
  });
}

}  // namespace datomsim::app
