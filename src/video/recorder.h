// Videos of the viewer (docs/videos.md): the page `datomsim view` writes, opened in headless
// Chromium in its video mode (no controls; the time, motions and notes as captions), drawn at
// each frame's trace time and encoded by ffmpeg. A scene with no changes turns once around.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "datomsim/result.h"

namespace datomsim::video {

enum class Container { kMp4, kWebm, kGif };

// The container a file name asks for, by its extension (.mp4, .webm, .gif); an error naming the
// file otherwise.
Result<Container> containerOf(const std::filesystem::path& file);

struct VideoRequest {
  std::string pageHtml;       // the viewer page (exporting::viewerHtml)
  std::filesystem::path out;  // .mp4 (H.264), .webm (VP9) or .gif
  int fps = 25;
  int width = 960;
  int height = 540;
  std::optional<double> from;  // trace seconds; default: the start
  std::optional<double> to;    // trace seconds; default: the end
  std::string view = "3d";     // "3d" or "top"
  // The sun's shadows: about 1.7 times the drawing time in headless Chromium's software renderer.
  bool shadows = false;
  // Trace seconds per video second; default: 1, or faster so that the video lasts `longest`.
  std::optional<double> speed;
  double longest = 20;
  std::string chromium;  // the browser; default: $CHROMIUM, else chromium in PATH
  std::string ffmpeg = "ffmpeg";
  // Called after each frame: frames written so far, frames in all.
  std::function<void(int, int)> progress;
};

// A scene's video turns once around in kSceneTurn seconds.
inline constexpr double kSceneTurn = 6;

struct VideoSummary {
  Container container = Container::kMp4;
  std::string codec;   // "H.264", "VP9", "GIF"
  int frames = 0;      // frames in the file
  int drawn = 0;       // frames the browser drew (the others repeat a picture)
  double seconds = 0;  // the video's length
  double from = 0;     // the trace times it shows
  double to = 0;
  double speed = 1;    // trace seconds per video second
  bool scene = false;  // a scene at rest, turned around
};

// Whether the browser and the encoder a request names (or the defaults) are installed; the error
// says which is missing and how to install it.
Status findVideoTools(const VideoRequest& request);

// Records the video into `out` (written whole or not at all). Errors name what failed: the
// browser or ffmpeg missing, the page, times outside the trace, the encoder's own message.
Result<VideoSummary> recordVideo(const VideoRequest& request);

}  // namespace datomsim::video
