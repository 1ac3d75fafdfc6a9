// `datomsim video` as a user runs it: a trace into an H.264 video of the length, size and frame
// rate asked, the same bytes twice; a scene turning around into a GIF, a trace from the top into
// a WebM; bad requests refused naming the value, with no video (nor a partial one) left behind.
// They need Chromium and ffmpeg (scripts/install-deps.sh installs both) and say so when either
// is missing.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <regex>
#include <string>

#include "command_line.h"
#include "support/temporary_directory.h"

namespace datomsim {
namespace {

using testing::readText;

class VideoCommand : public CommandLine {
 protected:
  void SetUp() override {
    for (const char* tool : {"chromium", "ffmpeg", "ffprobe"}) {
      if (shell(std::string("command -v ") + tool).status != 0) {
        GTEST_SKIP() << tool << " is not installed (scripts/install-deps.sh installs it)";
      }
    }
  }

  // ffprobe's figures of the first video stream: codec_name, width, height, nb_read_frames.
  std::string probe(const std::string& file) {
    return shell(
               "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
               "stream=codec_name,width,height,nb_read_frames -of default=noprint_wrappers=1 " +
               file)
        .output;
  }

  // The frames' checksums as ffmpeg decodes them, one line per frame.
  std::vector<std::string> frameChecksums(const std::string& file) {
    const Outcome sums = shell("ffmpeg -v error -i " + file + " -f framemd5 -");
    std::vector<std::string> checksums;
    static const std::regex kSum(R"(([0-9a-f]{32})$)");
    std::istringstream lines(sums.output);
    for (std::string line; std::getline(lines, line);) {
      std::smatch sum;
      if (line[0] != '#' && std::regex_search(line, sum, kSum)) checksums.push_back(sum[1]);
    }
    return checksums;
  }

  // A trace of the paper's run on the arch with the low hole (25 s: 9 motions of 2 s).
  std::string trace() {
    const std::string scene = arch(1);
    const std::string file = path("arch1.jsonl");
    EXPECT_EQ(datomsim("run " + scene +
                       " --program follow-gradient --goal 6,5,2 --start 0,0,2 -q --out " +
                       path("run.json") + " --trace " + file)
                  .status,
              0);
    return file;
  }
};

TEST_F(VideoCommand, RecordsATraceIntoAnMp4OfTheLengthSizeAndRateAsked) {
  const std::string input = trace();
  const std::string video = path("run.mp4");
  const Outcome made =
      datomsim("video " + input + " --from 0 --to 2 --size 320x180 --fps 10 -o " + video);
  ASSERT_EQ(made.status, 0) << made.output;
  // Trace 0..2 s at real time, 10 frames a second, and the end held one second: 31 frames.
  EXPECT_NE(made.output.find("wrote " + video +
                             " (H.264, 320x180, 10 fps, 3.1 s: trace 0.00 to "
                             "2.00 s at 1x; 31 frames,"),
            std::string::npos)
      << made.output;
  const std::string figures = probe(video);
  EXPECT_NE(figures.find("codec_name=h264"), std::string::npos) << figures;
  EXPECT_NE(figures.find("width=320\nheight=180"), std::string::npos) << figures;
  EXPECT_NE(figures.find("nb_read_frames=31"), std::string::npos) << figures;
  // The mobile moves in the first two seconds: the first and the 20th frames differ.
  const std::vector<std::string> frames = frameChecksums(video);
  ASSERT_EQ(frames.size(), 31u);
  EXPECT_NE(frames[0], frames[20]);
  // Same trace, same request: the same bytes.
  const std::string again = path("again.mp4");
  ASSERT_EQ(
      datomsim("video " + input + " --from 0 --to 2 --size 320x180 --fps 10 -q -o " + again).status,
      0);
  EXPECT_EQ(readText(video), readText(again));
  // Nothing else is left beside the video.
  EXPECT_FALSE(std::filesystem::exists(path(".run.mp4.partial")));
}

TEST_F(VideoCommand, ASceneTurnsAroundInAGifAndATraceSeenFromTheTopGoesIntoAWebm) {
  const Outcome gif =
      datomsim("video " + arch(2) + " --size 160x90 --fps 2 -o " + path("turn.gif"));
  ASSERT_EQ(gif.status, 0) << gif.output;
  EXPECT_NE(gif.output.find("the scene turning once around; 12 frames, 12 drawn"),
            std::string::npos)
      << gif.output;
  EXPECT_NE(probe(path("turn.gif")).find("codec_name=gif"), std::string::npos);
  // Turning, the pictures change.
  const std::vector<std::string> turn = frameChecksums(path("turn.gif"));
  ASSERT_EQ(turn.size(), 12u);
  EXPECT_NE(turn[0], turn[3]);

  const Outcome webm = datomsim("video " + trace() +
                                " --to 1 --size 160x90 --fps 4 --view top -o " + path("top.webm"));
  ASSERT_EQ(webm.status, 0) << webm.output;
  const std::string figures = probe(path("top.webm"));
  EXPECT_NE(figures.find("codec_name=vp9"), std::string::npos) << figures;
  EXPECT_NE(figures.find("nb_read_frames=9"), std::string::npos) << figures;  // 5, and 4 held
}

TEST_F(VideoCommand, BadRequestsAreRefusedNamingTheValueAndLeaveNoVideo) {
  const std::string input = trace();
  struct Case {
    std::string arguments;
    std::string says;
  };
  const std::string out = path("bad.mp4");
  const std::vector<Case> cases = {
      {"--size 321x180 -o " + out, "--size 321x180: the width must be even"},
      {"--size big -o " + out, "--size big: write WIDTHxHEIGHT"},
      {"--fps 0 -o " + out, "--fps 0 is outside 1..60"},
      {"-o " + path("bad.avi"), "a video is .mp4 (H.264), .webm (VP9) or .gif, not \".avi\""},
      {"--from 99 -o " + out, "--from 99 is not before the trace's end (24.93 s)"},
      {"--from 3 --to 2 -o " + out, "--to 2 must be after --from 3"},
      {"--view side -o " + out, "--view: side not in {3d,top}"},
      {"--chromium /no/such/chrome -o " + out, "--chromium /no/such/chrome is not an executable"},
  };
  for (const Case& c : cases) {
    const Outcome refused = datomsim("video " + input + " " + c.arguments);
    EXPECT_EQ(refused.status, 1) << c.arguments << "\n" << refused.output;
    EXPECT_NE(refused.output.find(c.says), std::string::npos) << c.arguments << "\n"
                                                              << refused.output;
  }
  // A special file is refused, not replaced by the renamed video (as root, -o /dev/null would
  // have replaced the system's own).
  const std::string fifo = path("special.mp4");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const Outcome special = datomsim("video " + input + " -o " + fifo);
  EXPECT_EQ(special.status, 1) << special.output;
  EXPECT_NE(special.output.find("-o " + fifo + ": not a regular file"), std::string::npos)
      << special.output;
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  const Outcome noBrowser = shell("CHROMIUM=/no/chrome " + std::string(DATOMSIM_BINARY) +
                                  " video " + input + " -o " + out);
  EXPECT_EQ(noBrowser.status, 1);
  EXPECT_NE(noBrowser.output.find("CHROMIUM=/no/chrome is not an executable"), std::string::npos)
      << noBrowser.output;
  for (const auto& entry : std::filesystem::directory_iterator(directory_.path())) {
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(name.find("bad"), std::string::npos) << name << " was left behind";
    EXPECT_EQ(name.find(".partial"), std::string::npos) << name << " was left behind";
  }
}

}  // namespace
}  // namespace datomsim
