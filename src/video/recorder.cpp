#include "video/recorder.h"

#include <signal.h>
#include <stdlib.h>

#include <fmt/format.h>
#include <cmath>
#include <fstream>
#include <vector>

#include "video/child_process.h"
#include "video/devtools.h"

namespace datomsim::video {

namespace {

using Json = nlohmann::json;

// A folder of the recording's own (the page, the browser's profile, the logs), removed at the end.
class ScratchFolder {
 public:
  static Result<ScratchFolder> make() {
    std::string pattern = (std::filesystem::temp_directory_path() / "datomsim-video-XXXXXX");
    if (::mkdtemp(pattern.data()) == nullptr) {
      return Error{fmt::format("cannot make a folder in {}", pattern)};
    }
    return ScratchFolder(pattern);
  }
  ScratchFolder(ScratchFolder&& other) noexcept : path_(std::move(other.path_)) {
    other.path_.clear();
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ~ScratchFolder() {
    std::error_code ignored;
    if (!path_.empty()) std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  explicit ScratchFolder(std::filesystem::path path) : path_(std::move(path)) {}
  std::filesystem::path path_;
};

// Writing to an encoder that has stopped must be an error to report, not SIGPIPE's silent end.
class IgnoreBrokenPipes {
 public:
  IgnoreBrokenPipes() {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &ignore, &previous_);
  }
  ~IgnoreBrokenPipes() { sigaction(SIGPIPE, &previous_, nullptr); }
  IgnoreBrokenPipes(const IgnoreBrokenPipes&) = delete;
  IgnoreBrokenPipes& operator=(const IgnoreBrokenPipes&) = delete;

 private:
  struct sigaction previous_ {};
};

// The last lines of a child's log, for an error message.
std::string logTail(const std::filesystem::path& log, size_t lines = 6) {
  std::ifstream in(log);
  std::vector<std::string> all;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) all.push_back(line);
  }
  std::string tail;
  for (size_t k = all.size() > lines ? all.size() - lines : 0; k < all.size(); ++k) {
    tail += "\n  " + all[k];
  }
  return tail;
}

// The browser: the one asked for, else $CHROMIUM, else the first of the usual names in PATH.
Result<std::string> findChromium(const std::string& asked) {
  const char* fromEnvironment = std::getenv("CHROMIUM");
  const std::string named = !asked.empty()                                   ? asked
                            : fromEnvironment != nullptr && *fromEnvironment ? fromEnvironment
                                                                             : "";
  if (!named.empty()) {
    const std::filesystem::path found = findExecutable(named);
    if (found.empty()) {
      return Error{fmt::format("{}{} is not an executable",
                               asked.empty() ? "CHROMIUM=" : "--chromium ", named)};
    }
    return found.string();
  }
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    if (const std::filesystem::path found = findExecutable(name); !found.empty()) {
      return found.string();
    }
  }
  return Error{
      "Chromium is not installed: videos are drawn by the viewer in headless Chromium "
      "(Debian: apt install chromium, or scripts/install-deps.sh; or set CHROMIUM or "
      "--chromium to a Chrome executable)"};
}

// ffmpeg's arguments after its input: codec, and the container written to `file`.
std::vector<std::string> encoderArguments(Container container, const std::string& file) {
  switch (container) {
    case Container::kMp4:
      return {"-c:v",    "libx264",   "-preset",    "medium", "-crf", "20", "-pix_fmt",
              "yuv420p", "-movflags", "+faststart", "-f",     "mp4",  file};
    case Container::kWebm:
      return {"-c:v",      "libvpx-vp9", "-crf",      "33",   "-b:v",    "0",
              "-deadline", "good",       "-cpu-used", "4",    "-row-mt", "1",
              "-pix_fmt",  "yuv420p",    "-f",        "webm", file};
    case Container::kGif:
      // One palette for the whole video, made from what changes, dithered lightly.
      return {"-filter_complex",
              "[0:v]split[a][b];[a]palettegen=stats_mode=diff[p];"
              "[b][p]paletteuse=dither=bayer:bayer_scale=4:diff_mode=rectangle",
              "-loop",
              "0",
              "-f",
              "gif",
              file};
  }
  return {};
}

const char* codecName(Container container) {
  switch (container) {
    case Container::kMp4:
      return "H.264";
    case Container::kWebm:
      return "VP9";
    case Container::kGif:
      return "GIF";
  }
  return "";
}

Status checkRequest(const VideoRequest& request) {
  if (request.fps < 1 || request.fps > 60) {
    return Error{fmt::format("--fps {} is outside 1..60", request.fps)};
  }
  for (const auto& [name, pixels] :
       {std::pair{"width", request.width}, {"height", request.height}}) {
    if (pixels < 64 || pixels > 3840 || pixels % 2 != 0) {
      return Error{fmt::format(
          "--size {}x{}: the {} must be even and within 64..3840 pixels (the encoders need even "
          "sizes)",
          request.width, request.height, name)};
    }
  }
  if (request.view != "3d" && request.view != "top") {
    return Error{fmt::format("--view {}: choose 3d or top", request.view)};
  }
  if (request.speed && !(std::isfinite(*request.speed) && *request.speed > 0)) {
    return Error{
        fmt::format("--speed {}: trace seconds per video second, above 0", *request.speed)};
  }
  for (const auto& [name, time] : {std::pair{"--from", request.from}, {"--to", request.to}}) {
    if (time && !(std::isfinite(*time) && *time >= 0)) {
      return Error{fmt::format("{} {}: a trace time in seconds, 0 or more", name, *time)};
    }
  }
  return Ok{};
}

// The browser with the page open in video mode; the session to its page.
struct OpenPage {
  ChildProcess browser;
  DevTools devtools;
  std::string session;
};

Result<OpenPage> openPage(const std::string& chromium, const std::filesystem::path& page,
                          const VideoRequest& request, const std::filesystem::path& scratch) {
  const std::vector<std::string> argv = {
      chromium, "--headless", "--no-sandbox", "--disable-gpu",
      // WebGL without a GPU: SwiftShader, which Chromium only allows when asked.
      "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--remote-debugging-pipe",
      "--user-data-dir=" + (scratch / "profile").string(), "--no-first-run",
      "--no-default-browser-check", "--disable-background-networking", "--disable-component-update",
      "--disable-sync", "--disable-extensions", "--hide-scrollbars", "--mute-audio",
      "--disable-background-timer-throttling", "--disable-renderer-backgrounding",
      fmt::format("--window-size={},{}", request.width, request.height), "about:blank"};
  const std::filesystem::path log = scratch / "chromium.log";
  Result<ChildProcess> started = ChildProcess::start(argv, {.devtoolsPipes = true, .log = log});
  if (!started) return Error{started.error()};
  const int commands = started->commandsFd(), replies = started->repliesFd();
  OpenPage open{std::move(*started), DevTools(commands, replies, std::chrono::seconds(60)), ""};
  const auto failed = [&](const std::string& what) -> Result<OpenPage> {
    return Error{fmt::format("Chromium ({}): {}{}", chromium, what, logTail(log))};
  };
  DevTools& devtools = open.devtools;
  auto target = devtools.call("Target.createTarget", {{"url", "about:blank"}});
  if (!target) return failed(target.error());
  auto attached = devtools.call("Target.attachToTarget",
                                {{"targetId", (*target)["targetId"]}, {"flatten", true}});
  if (!attached) return failed(attached.error());
  open.session = (*attached)["sessionId"].get<std::string>();
  auto metrics = devtools.call("Emulation.setDeviceMetricsOverride",
                               {{"width", request.width},
                                {"height", request.height},
                                {"deviceScaleFactor", 1},
                                {"mobile", false}},
                               open.session);
  if (!metrics) return failed(metrics.error());
  const std::string url = fmt::format("file://{}#view={}{}&video", page.string(), request.view,
                                      request.shadows ? "" : "&shadows=off");
  auto navigated = devtools.call("Page.navigate", {{"url", url}}, open.session);
  if (!navigated) return failed(navigated.error());

  // The viewer is ready, or the page shows why not.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (true) {
    auto state = devtools.evaluate(
        "window.datomsimViewer && window.datomsimViewer.ready ? 'ready' : "
        "(document.querySelector('.dv-error') ? document.querySelector('.dv-error').textContent "
        ": '')",
        open.session);
    if (!state) return failed(state.error());
    if (state->is_string() && *state == "ready") break;
    if (state->is_string() && !state->get<std::string>().empty()) {
      return Error{fmt::format("the viewer page cannot show it: {}", state->get<std::string>())};
    }
    if (std::chrono::steady_clock::now() > deadline) {
      return failed("the viewer did not start within 60 s");
    }
    ::usleep(50'000);
  }
  return open;
}

}  // namespace

Result<Container> containerOf(const std::filesystem::path& file) {
  const std::string extension = file.extension().string();
  if (extension == ".mp4") return Container::kMp4;
  if (extension == ".webm") return Container::kWebm;
  if (extension == ".gif") return Container::kGif;
  return Error{fmt::format("{}: a video is .mp4 (H.264), .webm (VP9) or .gif, not \"{}\"",
                           file.string(), extension)};
}

Status findVideoTools(const VideoRequest& request) {
  if (Result<std::string> chromium = findChromium(request.chromium); !chromium) {
    return Error{chromium.error()};
  }
  if (findExecutable(request.ffmpeg).empty()) {
    return Error{fmt::format(
        "{} is not installed: videos are encoded by ffmpeg (Debian: apt install ffmpeg, or "
        "scripts/install-deps.sh)",
        request.ffmpeg)};
  }
  return Ok{};
}

Result<VideoSummary> recordVideo(const VideoRequest& request) {
  if (Status valid = checkRequest(request); !valid) return Error{valid.error()};
  Result<Container> container = containerOf(request.out);
  if (!container) return Error{container.error()};
  if (Status tools = findVideoTools(request); !tools) return Error{tools.error()};
  const std::string chromium = *findChromium(request.chromium);

  Result<ScratchFolder> scratch = ScratchFolder::make();
  if (!scratch) return Error{scratch.error()};
  const std::filesystem::path page = scratch->path() / "page.html";
  {
    std::ofstream file(page, std::ios::binary);
    file << request.pageHtml;
    if (!file) return Error{fmt::format("cannot write {}", page.string())};
  }
  Result<OpenPage> opened = openPage(chromium, page, request, scratch->path());
  if (!opened) return Error{opened.error()};
  OpenPage& open = *opened;

  // The frames: trace times from..to at `speed` trace seconds per video second, or a scene's turn.
  VideoSummary summary;
  summary.container = *container;
  summary.codec = codecName(*container);
  auto duration = open.devtools.evaluate("window.datomsimViewer.duration", open.session);
  if (!duration) return Error{duration.error()};
  const double traceLength = duration->is_number() ? duration->get<double>() : 0;
  summary.scene = traceLength <= 0;
  std::vector<std::string> frameCalls;
  if (summary.scene) {
    if (request.from || request.to) {
      return Error{"--from and --to are trace times: a scene has none (it turns around once)"};
    }
    const int frames = int(std::lround(kSceneTurn * request.fps));
    for (int k = 0; k < frames; ++k) {
      frameCalls.push_back(
          fmt::format("window.datomsimViewer.videoTurn({:.6f})", 360.0 * k / frames));
    }
    summary.speed = 0;
  } else {
    summary.from = request.from.value_or(0);
    summary.to = request.to.value_or(traceLength);
    if (summary.from >= traceLength) {
      return Error{fmt::format("--from {} is not before the trace's end ({:.2f} s)", summary.from,
                               traceLength)};
    }
    if (summary.to > traceLength + 1e-9 || summary.to <= summary.from) {
      return Error{
          fmt::format("--to {} must be after --from {} and at most the trace's end "
                      "({:.2f} s)",
                      summary.to, summary.from, traceLength)};
    }
    const double span = summary.to - summary.from;
    summary.speed = request.speed.value_or(span <= request.longest ? 1.0 : span / request.longest);
    const int steps = int(std::floor(span / summary.speed * request.fps + 1e-9));
    for (int k = 0; k <= steps; ++k) {
      const double t = std::min(summary.to, summary.from + k * summary.speed / request.fps);
      frameCalls.push_back(fmt::format("window.datomsimViewer.videoFrame({:.6f})", t));
    }
    // The last frame shows the end itself, then it is held a second, so that a viewer sees how
    // the run ended.
    if (summary.from + steps * summary.speed / request.fps < summary.to - 1e-9) {
      frameCalls.push_back(fmt::format("window.datomsimViewer.videoFrame({:.6f})", summary.to));
    }
    for (int k = 0; k < request.fps; ++k) frameCalls.push_back(frameCalls.back());
  }
  summary.frames = int(frameCalls.size());
  summary.seconds = double(summary.frames) / request.fps;

  // ffmpeg writes a hidden partial file, renamed when whole.
  const std::filesystem::path partial =
      request.out.parent_path() / ("." + request.out.filename().string() + ".partial");
  const std::filesystem::path encoderLog = scratch->path() / "ffmpeg.log";
  std::vector<std::string> argv = {request.ffmpeg,
                                   "-hide_banner",
                                   "-loglevel",
                                   "error",
                                   "-y",
                                   "-f",
                                   "image2pipe",
                                   "-framerate",
                                   std::to_string(request.fps),
                                   "-c:v",
                                   "mjpeg",
                                   "-i",
                                   "-",
                                   "-fflags",
                                   "+bitexact",
                                   "-flags:v",
                                   "+bitexact",
                                   "-map_metadata",
                                   "-1"};
  for (std::string& argument : encoderArguments(*container, partial.string())) {
    argv.push_back(std::move(argument));
  }
  IgnoreBrokenPipes ignoreBrokenPipes;
  Result<ChildProcess> encoder = ChildProcess::start(argv, {.pipeInput = true, .log = encoderLog});
  if (!encoder) return Error{encoder.error()};
  const auto removePartial = [&] {
    std::error_code ignored;
    std::filesystem::remove(partial, ignored);
  };
  // Every failure from here on stops the encoder and leaves no partial file.
  const auto stop = [&](std::string message) -> Result<VideoSummary> {
    encoder->kill();
    removePartial();
    return Error{std::move(message)};
  };

  std::string lastKey, lastPicture;
  for (size_t k = 0; k < frameCalls.size(); ++k) {
    auto key = open.devtools.evaluate(frameCalls[k], open.session);
    if (!key) return stop(key.error());
    const std::string name = key->is_string() ? key->get<std::string>() : key->dump();
    if (k == 0 || name != lastKey) {
      auto shot = open.devtools.call("Page.captureScreenshot",
                                     {{"format", "jpeg"}, {"quality", 92}, {"fromSurface", true}},
                                     open.session);
      if (!shot) return stop(shot.error());
      auto picture = decodeBase64((*shot)["data"].get<std::string>());
      if (!picture) return stop("the browser sent no picture: " + picture.error());
      lastPicture = std::move(*picture);
      lastKey = name;
      ++summary.drawn;
    }
    if (Status written = encoder->writeInput(lastPicture); !written) {
      return stop(
          fmt::format("ffmpeg stopped taking frames ({}){}", written.error(), logTail(encoderLog)));
    }
    if (request.progress) request.progress(int(k + 1), summary.frames);
  }
  open.devtools.call("Browser.close").ok();  // the browser may be gone before it answers
  open.browser.kill();
  encoder->closeInput();
  if (const int status = encoder->wait(); status != 0) {
    removePartial();
    return Error{fmt::format("ffmpeg failed (exit status {}) writing {}{}", status,
                             request.out.string(), logTail(encoderLog))};
  }
  std::error_code error;
  std::filesystem::rename(partial, request.out, error);
  if (error) {
    removePartial();
    return Error{fmt::format("cannot write {}: {}", request.out.string(), error.message())};
  }
  return summary;
}

}  // namespace datomsim::video
