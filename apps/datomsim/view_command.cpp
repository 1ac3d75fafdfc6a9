// `view` and `video`: the viewer's page of a trace or a scene, as one self-contained HTML file to
// open in a browser, or recorded frame by frame into a video (docs/viewer.md, docs/videos.md).
#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <filesystem>

#include "commands.h"
#include "export/loads_check.h"
#include "export/viewer_page.h"
#include "video/recorder.h"

namespace datomsim::app {

namespace {

// What both commands take to make the page.
struct PageArguments {
  std::string input, reach, loads, viewerJs, title;
};

void addPageOptions(CLI::App& command, PageArguments& page) {
  command
      .add_option("input", page.input, "Trace (datomsim run --trace) or scene file (.xml or .json)")
      ->required();
  command.add_option("--reach", page.reach,
                     "A distance map and path to show: the JSON of `datomsim reach --out`");
  command.add_option("--loads", page.loads,
                     "Latch loads to colour the latches by: the JSON of `datomsim loads --out` "
                     "for the same scene (a trace's: its start)");
  command.add_option("--title", page.title, "Title of the page (default: the trace's description)");
  command.add_option("--viewer-js", page.viewerJs,
                     "The viewer script to inline (default: viewer.bundle.js next to the binary)");
}

exporting::ViewerPage pageOf(const PageArguments& arguments) {
  exporting::ViewerPage page = unwrap(exporting::pageForFile(arguments.input));
  if (!arguments.reach.empty()) {
    page.overlay = unwrap(
        exporting::checkOverlay(unwrap(exporting::readFile(arguments.reach)), arguments.reach));
  }
  if (!arguments.loads.empty()) {
    page.loads = unwrap(exporting::checkLoads(unwrap(exporting::readFile(arguments.loads)),
                                              arguments.loads, page.trace));
  }
  if (!arguments.title.empty()) page.title = arguments.title;
  return page;
}

std::string bundleFor(const PageArguments& arguments) {
  const std::filesystem::path here =
      arguments.viewerJs.empty() ? unwrap(exporting::executableDirectory()) : "";
  return unwrap(exporting::loadViewerBundle(arguments.viewerJs, here));
}

// The output's default: the input's name with `extension` added, so that a scene and its trace
// (x.json, x.jsonl) never write the same file.
std::string outputFor(const std::string& out, const std::string& input,
                      const std::string& extension) {
  return out.empty() ? input + extension : out;
}

// Every file the page reads, for the outputs to be checked against.
std::vector<NamedPath> inputsOf(const PageArguments& page) {
  std::vector<NamedPath> inputs = {{"input", page.input}};
  if (!page.reach.empty()) inputs.push_back({"--reach", page.reach});
  if (!page.loads.empty()) inputs.push_back({"--loads", page.loads});
  if (!page.viewerJs.empty()) inputs.push_back({"--viewer-js", page.viewerJs});
  return inputs;
}

// "1280x720" -> {1280, 720}. Read with from_chars: sscanf's %d wraps a number beyond int, and the
// message would echo another number than the one given.
std::pair<int, int> parseSize(const std::string& text) {
  int width = 0, height = 0;
  const char* const end = text.data() + text.size();
  const auto [afterWidth, widthError] = std::from_chars(text.data(), end, width);
  const bool separated = widthError == std::errc() && afterWidth != end && *afterWidth == 'x';
  const auto [afterHeight, heightError] =
      separated ? std::from_chars(afterWidth + 1, end, height) : std::from_chars_result{};
  if (!separated || heightError != std::errc() || afterHeight != end) {
    throw UsageError(fmt::format(
        "--size {}: write WIDTHxHEIGHT in pixels, each within 64..3840, e.g. 1280x720", text));
  }
  return {width, height};
}

}  // namespace

std::function<void(int, int)> videoProgress(const std::string& name, const Reporter& reporter) {
  // A count of frames on a terminal; nothing in a log.
  if (reporter.quiet() || !::isatty(STDERR_FILENO)) return {};
  return [name](int done, int total) {
    fmt::print(stderr, "\r{}: frame {}/{}", name, done, total);
    if (done == total) fmt::print(stderr, "\r\033[K");
  };
}

std::string describeVideo(const video::VideoSummary& made, const video::VideoRequest& request) {
  const std::string shows = made.scene ? "the scene turning once around"
                                       : fmt::format("trace {:.2f} to {:.2f} s at {:g}x", made.from,
                                                     made.to, std::round(made.speed * 1000) / 1000);
  return fmt::format("{}, {}x{}, {} fps, {:.1f} s: {}; {} frames, {} drawn", made.codec,
                     request.width, request.height, request.fps, made.seconds, shows, made.frames,
                     made.drawn);
}

void addViewCommand(CLI::App& app, const Reporter& reporter) {
  struct Arguments {
    PageArguments page;
    std::string out;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "view",
      "Write one HTML page that replays a trace (or shows a scene) in 3D; it works offline from "
      "disk (docs/viewer.md)");
  addPageOptions(*command, args->page);
  command->add_option("-o,--out", args->out,
                      "HTML file to write (default: the input's name with .html added, so that a "
                      "scene and its trace, x.json and x.jsonl, give two pages)");
  addExample(*command, "view scenes/walkers.json -o walkers.html");
  command->callback([args, &reporter] {
    // The page is a file: "-" names one, as for video.
    const std::string out = outputFor(args->out, args->page.input, ".html");
    CommandFiles files(inputsOf(args->page), {{"-o", out == "-" ? "./-" : out}});
    files.write("-o", unwrap(exporting::viewerHtml(bundleFor(args->page), pageOf(args->page))));
    files.commit(reporter);
  });
}

void addVideoCommand(CLI::App& app, const Reporter& reporter) {
  struct Arguments {
    PageArguments page;
    std::string out, size = "960x540", view = "3d", chromium;
    int fps = 25;
    bool shadows = false;
    std::optional<double> from, to, speed;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "video",
      "Record the viewer replaying a trace (or turning around a scene) into an .mp4, .webm or "
      ".gif, with headless Chromium and ffmpeg (docs/videos.md)");
  addPageOptions(*command, args->page);
  command->add_option("-o,--out", args->out,
                      "Video to write: .mp4 (H.264), .webm (VP9) or .gif (default: the input's "
                      "name with .mp4 added)");
  command->add_option("--fps", args->fps, "Frames per second")->capture_default_str();
  command->add_option("--size", args->size, "Frame size WIDTHxHEIGHT in pixels (even)")
      ->capture_default_str();
  command->add_option("--from", args->from, "First trace time shown, in seconds (default: 0)");
  command->add_option("--to", args->to, "Last trace time shown, in seconds (default: the end)");
  command->add_option("--speed", args->speed,
                      "Trace seconds per video second (default: 1, or faster so that the video "
                      "lasts 20 s)");
  command->add_option("--view", args->view, "Camera: 3d (front left, above) or top")
      ->check(CLI::IsMember({"3d", "top"}))
      ->capture_default_str();
  command->add_flag("--shadows", args->shadows,
                    "Draw the sun's shadows on the ground (about 1.7 times the drawing time)");
  command->add_option("--chromium", args->chromium,
                      "The browser that draws the frames (default: $CHROMIUM, else chromium)");
  addExample(*command, "video scenes/paper-arch-hole1.json --size 320x180 --fps 8 -o arch1.gif");
  command->callback([args, &reporter] {
    video::VideoRequest request;
    request.out = outputFor(args->out, args->page.input, ".mp4");
    // ffmpeg writes the video (to a partial file renamed at the end: video/recorder.h).
    frontend::refuseClashes(inputsOf(args->page), {{"-o", request.out.string()}});
    // The partial file is renamed onto the output, which would replace a device or a FIFO (as
    // root, /dev/null itself) and a symbolic link: a special file is refused, a link followed.
    std::error_code error;
    if (const auto status = std::filesystem::status(request.out, error);
        !error && std::filesystem::exists(status)) {
      if (!std::filesystem::is_regular_file(status)) {
        throw UsageError(fmt::format(
            "-o {}: not a regular file; a video is written to a file of its own (ffmpeg makes it "
            "whole, then it is renamed into place)",
            request.out.string()));
      }
      request.out = std::filesystem::canonical(request.out);
    }
    unwrap(video::containerOf(request.out));  // before the page is made
    std::tie(request.width, request.height) = parseSize(args->size);
    request.fps = args->fps;
    request.from = args->from;
    request.to = args->to;
    request.speed = args->speed;
    request.view = args->view;
    request.shadows = args->shadows;
    request.chromium = args->chromium;
    request.pageHtml = unwrap(exporting::viewerHtml(bundleFor(args->page), pageOf(args->page)));
    request.progress = videoProgress(request.out.filename().string(), reporter);
    const video::VideoSummary made = unwrap(video::recordVideo(request));
    reporter.reportWritten(request.out.string(), describeVideo(made, request));
  });
}

}  // namespace datomsim::app
