// The time options of `run` (--until, --timeout in seconds; --delay-ms, --jitter-ms in
// milliseconds) as a user mistypes them: NaN, infinities, negatives and times beyond the bounds of
// docs/limits.md are refused naming the option and the value, before anything runs and without
// leaving an output behind; times at the bounds run and report what they were asked.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "command_line.h"

namespace datomsim {
namespace {

using testing::readText;

class TimeOptions : public CommandLine {
 protected:
  // A small box flooded from a corner: a run of a few messages that falls quiet.
  std::string flood() {
    const std::string box = path("box.json");
    EXPECT_EQ(datomsim("generate box --size 3,2,2 -o " + box).status, 0);
    return "run " + box + " --program flood --root 0,0,0 ";
  }
  // A reconfiguration, which alone takes --timeout.
  std::string reconfigure() {
    const std::string line = path("line.json");
    EXPECT_EQ(datomsim("generate reshape line -o " + line).status, 0);
    return "run " + line + " --program reconfigure ";
  }
  // Runs `arguments` with --out and --trace, which must fail with `message` and write neither.
  void refused(const std::string& arguments, const std::string& message) {
    const std::string out = path("run.json"), trace = path("trace.json");
    const Outcome outcome = datomsim(arguments + " --out " + out + " --trace " + trace);
    EXPECT_EQ(outcome.status, 1) << arguments << "\n" << outcome.output;
    EXPECT_EQ(outcome.output, "datomsim: error: " + message + "\n") << arguments;
    EXPECT_FALSE(std::filesystem::exists(out)) << arguments;
    EXPECT_FALSE(std::filesystem::exists(trace)) << arguments;
  }
};

TEST_F(TimeOptions, UntilBeyondThirtyOneYearsIsRefusedRatherThanRunningNoEvent) {
  const std::string run = flood();
  refused(run + "--until 1e13",
          "--until 10000000000000: at most 1e9 seconds, about 31 years (docs/limits.md)");
  refused(run + "--until 1000000001",
          "--until 1000000001: at most 1e9 seconds, about 31 years (docs/limits.md)");
  refused(run + "--until 1e300",
          "--until 1e+300: at most 1e9 seconds, about 31 years (docs/limits.md)");
}

TEST_F(TimeOptions, UntilMustBeAFiniteNumberAboveZero) {
  const std::string run = flood();
  refused(run + "--until nan", "--until nan: a finite number of seconds, above 0");
  refused(run + "--until inf", "--until inf: a finite number of seconds, above 0");
  refused(run + "--until -1", "--until -1: a finite number of seconds, above 0");
  refused(run + "--until 0", "--until 0: a finite number of seconds, above 0");
}

TEST_F(TimeOptions, TimeoutBeyondThirtyOneYearsIsRefusedRatherThanGoingNegative) {
  const std::string run = reconfigure();
  refused(run + "--timeout 1e13",
          "--timeout 10000000000000: at most 1e9 seconds, about 31 years (docs/limits.md)");
  refused(run + "--timeout nan", "--timeout nan: a finite number of seconds, above 0");
  refused(run + "--timeout -5", "--timeout -5: a finite number of seconds, above 0");
  refused(run + "--timeout 0", "--timeout 0: a finite number of seconds, above 0");
}

TEST_F(TimeOptions, DelaysBeyondAMillionSecondsAreRefusedRatherThanWrapping) {
  const std::string run = flood();
  for (const std::string option : {"--delay-ms", "--jitter-ms"}) {
    refused(run + option + " 1e16",
            option + " 1e+16: at most 1e9 milliseconds, about 11.6 days (docs/limits.md)");
    refused(run + option + " nan", option + " nan: a finite number of milliseconds, 0 or more");
    refused(run + option + " -inf", option + " -inf: a finite number of milliseconds, 0 or more");
    refused(run + option + " -0.5", option + " -0.5: a finite number of milliseconds, 0 or more");
  }
}

TEST_F(TimeOptions, TimesAtTheBoundsRunAndReportPositiveTimes) {
  const std::string run = flood();
  // The longest delay and jitter: messages a million seconds apart, and time goes forward.
  const Outcome slow =
      datomsim(run + "--delay-ms 1e9 --jitter-ms 1e9 --until 1e9 --out " + path("slow.json"));
  ASSERT_EQ(slow.status, 0) << slow.output;
  const auto json = nlohmann::json::parse(readText(path("slow.json")));
  EXPECT_GE(json["sim_time_s"].get<double>(), 1e6);
  EXPECT_LE(json["sim_time_s"].get<double>(), 1e9);
  EXPECT_GT(json["messages"].get<int>(), 0);
  // A zero delay is allowed: every message arrives at once.
  const Outcome instant = datomsim(run + "--delay-ms 0 --out " + path("instant.json"));
  ASSERT_EQ(instant.status, 0) << instant.output;
  EXPECT_EQ(nlohmann::json::parse(readText(path("instant.json")))["sim_time_s"], 0.0);
}

TEST_F(TimeOptions, TimeoutAtTheBoundRuns) {
  const Outcome run = datomsim(reconfigure() + "--timeout 1e9 --out " + path("run.json"));
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(nlohmann::json::parse(readText(path("run.json")))["program"], "reconfigure");
}

}  // namespace
}  // namespace datomsim
