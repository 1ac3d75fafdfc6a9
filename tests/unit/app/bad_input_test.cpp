// Bad input as a hostile user gives it: every case ends with a message naming the file, line,
// option or value, exit status 1, and no output left behind as if it were good.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "command_line.h"

// GCC says so with __SANITIZE_ADDRESS__, Clang with __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define DATOMSIM_UNDER_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DATOMSIM_UNDER_ADDRESS_SANITIZER 1
#endif
#endif
#ifndef DATOMSIM_UNDER_ADDRESS_SANITIZER
#define DATOMSIM_UNDER_ADDRESS_SANITIZER 0
#endif

namespace datomsim {
namespace {

using testing::readText;

class BadInput : public CommandLine {
 protected:
  void write(const std::string& name, const std::string& text) {
    std::ofstream(path(name), std::ios::binary) << text;
  }
  std::string box() {
    if (!std::filesystem::exists(path("box.json"))) {
      EXPECT_EQ(datomsim("generate box --size 3,2,2 -o " + path("box.json")).status, 0);
    }
    return path("box.json");
  }
  // Runs a command that must fail with `message` in its output and leave `output` unwritten.
  void refused(const std::string& arguments, const std::string& message,
               const std::string& output = "") {
    const Outcome outcome = datomsim(arguments);
    EXPECT_EQ(outcome.status, 1) << arguments << "\n" << outcome.output;
    EXPECT_NE(outcome.output.find(message), std::string::npos)
        << arguments << "\nexpected: " << message << "\ngot: " << outcome.output;
    if (!output.empty()) {
      EXPECT_FALSE(std::filesystem::exists(output)) << arguments;
    }
  }
};

TEST_F(BadInput, DeeplyNestedJsonIsRefusedWithoutExhaustingTheStack) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  write("scene.json",
        R"({"format":"datomsim-scene","version":1,"name":)" + deep + R"(,"modules":[]})");
  refused("info " + path("scene.json"), "scene.json: name: values nested deeper than 32 levels");
  write("module.json",
        R"({"format":"datomsim-scene","version":1,"modules":[{"cell":)" + deep + "}]}");
  refused("info " + path("module.json"), "values nested deeper than 32 levels");
  write("reach.json", R"({"distances":)" + deep + "}");
  refused("view " + box() + " --reach " + path("reach.json") + " -o " + path("page.html"),
          "reach.json:1: values nested deeper than 32 levels", path("page.html"));
  write("trace.jsonl", readText(box()) + "\n");  // not a trace; nested values below it
  const Outcome run =
      datomsim("run " + box() + " --program flood --root 0,0,0 --trace " + path("good.jsonl"));
  ASSERT_EQ(run.status, 0) << run.output;
  write("deep.jsonl", readText(path("good.jsonl")) + R"({"t":1,"note":)" + deep + "}\n");
  refused("view " + path("deep.jsonl") + " -o " + path("deep.html"),
          "values nested deeper than 32 levels", path("deep.html"));
}

TEST_F(BadInput, MalformedXmlIsRefusedNamingTheLine) {
  ASSERT_EQ(datomsim("generate box --size 2,1,1 -o " + path("s.xml")).status, 0);
  const std::string good = readText(path("s.xml"));
  const std::pair<std::string, std::string> cases[] = {
      {"a&b", "\"&b\" is no character reference: write & as &amp;"},
      {"a&foo;b", "\"&foo;\" is no character reference"},
      {"a&#0;b", "\"&#0;\" is no character reference"},
      {"a&#xFFFFFFFF;b", "\"&#xFFFFFFFF;\" is no character reference"},
      {"x&lt", "\"&lt\" is no character reference"},
      {"a\x01z", "control character U+0001 is not allowed"},
  };
  for (const auto& [name, message] : cases) {
    std::string text = good;
    const size_t at = text.find("name=\"") + 6;
    text.replace(at, text.find('"', at) - at, name);
    write("bad.xml", text);
    refused("convert " + path("bad.xml") + " -o " + path("bad.json"),
            "bad.xml:2: malformed XML: " + message, path("bad.json"));
  }
  // What is well formed still reads, references and all.
  std::string text = good;
  text.replace(text.find("name=\"") + 6, 9, "a&amp;b&#x41;&#66;");
  write("fine.xml", text);
  ASSERT_EQ(datomsim("convert " + path("fine.xml") + " -o " + path("fine.json")).status, 0);
  EXPECT_NE(readText(path("fine.json")).find("\"name\": \"a&bAB\""), std::string::npos);
}

TEST_F(BadInput, TextXmlCannotHoldIsRefusedRatherThanCutOrWrittenRaw) {
  // tinyxml2 would end the name at the NUL, and write U+0001 raw (no XML reader takes it back).
  for (const auto& [field, escaped, code] : {std::tuple{"name", "a\\u0000b", "U+0000"},
                                             std::tuple{"description", "x\\u0001", "U+0001"}}) {
    write("text.json", std::string(R"({"format":"datomsim-scene","version":1,")") + field +
                           R"(":")" + escaped + R"(","modules":[{"cell":[0,0,0]}]})");
    refused("convert " + path("text.json") + " -o " + path("text.xml"),
            std::string("the scene's ") + field + " holds the control character " + code +
                ", which XML cannot hold",
            path("text.xml"));
  }
  // Tabs and line feeds are text XML holds: the round trip keeps them.
  write("tab.json", R"({"format":"datomsim-scene","version":1,"name":"a\tb\nc","modules":[]})");
  ASSERT_EQ(datomsim("convert " + path("tab.json") + " -o " + path("tab.xml")).status, 0);
  ASSERT_EQ(datomsim("convert " + path("tab.xml") + " -o " + path("back.json")).status, 0);
  EXPECT_NE(readText(path("back.json")).find(R"("name": "a\tb\nc")"), std::string::npos)
      << readText(path("back.json"));
}

TEST_F(BadInput, SizesBeyondTheLimitsAreRefusedUpFront) {
  refused("generate box --size 60000,60000,1 -o " + path("huge.json"),
          "a box of 60000,60000,1 is 3600000000 modules; a world holds at most 200000000",
          path("huge.json"));
  refused("generate random --count 300000000 -o " + path("r.json"),
          "random scene: 300000000 modules; a world holds at most 200000000", path("r.json"));
  refused("generate reshape pyramid --side 20000 -o " + path("p.json"),
          "is more modules than a world holds", path("p.json"));
  // Counted before the floor's side is: 2147483644 + 4 overflowed into "at least 2 by 2".
  refused("generate reshape line --length 2147483644 -o " + path("l.json"),
          "a line of 2147483644 modules stands on a floor of 17179869184 modules: 19327352828 in "
          "all, more than the 200000000 a world may hold",
          path("l.json"));
  // A device is no scene file: it would be read until memory runs out.
  refused("info /dev/zero", "");
  std::filesystem::create_symlink("/dev/zero", path("zero.xml"));
  refused("info " + path("zero.xml"), "zero.xml: is not a regular file");
}

// Within the module limit but beyond what the process may take: refused before anything is
// allocated, rather than killed half-way. The limit is set as a user would, with ulimit -v.
TEST_F(BadInput, ABoxBeyondTheMemoryAvailableIsRefusedUpFront) {
#if DATOMSIM_UNDER_ADDRESS_SANITIZER
  GTEST_SKIP() << "AddressSanitizer reserves more address space than ulimit -v allows";
#else
  const Outcome outcome = shell("ulimit -v 1000000 && " + std::string(DATOMSIM_BINARY) +
                                " generate box --size 10000,10000,1 -o " + path("big.json"));
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("a box of 10000,10000,1 is 100000000 modules, about 4.2 GB to "
                                "generate; this process may take 1.0 GB"),
            std::string::npos)
      << outcome.output;
  EXPECT_FALSE(std::filesystem::exists(path("big.json")));
#endif
}

// The same for the other generators that can be asked for scenes of millions of modules.
TEST_F(BadInput, OtherGeneratorsBeyondTheMemoryAvailableAreRefusedUpFront) {
#if DATOMSIM_UNDER_ADDRESS_SANITIZER
  GTEST_SKIP() << "AddressSanitizer reserves more address space than ulimit -v allows";
#else
  const std::vector<std::pair<std::string, std::string> > cases = {
      {"random --count 100000000",
       "a random scene of --count 100000000 is 100000000 modules, about 10.2 GB to generate"},
      {"reshape random --floor 10000,10000 --modules 100",
       "the reshape case random is about 100000100 modules"},
      {"reshape line --length 10000000", "the reshape case line is about 90000032 modules"},
      {"reshape cube --side 4000", "the reshape case cube is about 141000000 modules"},
      {"reshape pyramid --side 4000", "the reshape case pyramid is about 57791750 modules"},
      {"reshape heap --floor 10000,10000", "the reshape case heap is about 133333333 modules"},
  };
  for (const auto& [arguments, message] : cases) {
    const Outcome outcome = shell("ulimit -v 1000000 && " + std::string(DATOMSIM_BINARY) +
                                  " generate " + arguments + " -o " + path("big.json"));
    EXPECT_EQ(outcome.status, 1) << arguments << ": " << outcome.output;
    EXPECT_NE(outcome.output.find(message), std::string::npos)
        << arguments << ": " << outcome.output;
    EXPECT_NE(outcome.output.find("this process may take 1.0 GB"), std::string::npos)
        << arguments << ": " << outcome.output;
    EXPECT_FALSE(std::filesystem::exists(path("big.json")));
  }
#endif
}

TEST_F(BadInput, CoordinatesOutsideTheSupportedRangeAreRefusedAtEveryEntry) {
  refused("generate box --size 3,1,1 --origin 2147483646,0,0 -o " + path("e.json"),
          "--origin \"2147483646,0,0\": 2147483646 is outside the supported coordinate range, "
          "-1048576 to 1048575",
          path("e.json"));
  refused("generate box --size 3,1,1 --origin 1048574,0,0 -o " + path("e.json"),
          "leaves the supported coordinate range", path("e.json"));
  refused("reach " + box() + " --goal 1048576,0,0", "is outside the supported coordinate range");
  write("far.json",
        R"({"format":"datomsim-scene","version":1,"modules":[{"cell":[1048576,0,0]}]})");
  refused("info " + path("far.json"), "is outside the supported coordinate range");
  // Modules at both ends of the range are far apart, not neighbours (their packed keys would
  // alias if a cell beyond the range were looked up).
  write("ends.json", R"({"format":"datomsim-scene","version":1,"modules":[)"
                     R"({"cell":[1048575,0,0]},{"cell":[-1048576,0,0]},)"
                     R"({"cell":[0,1048575,100]},{"cell":[0,-1048576,0]}]})");
  const Outcome info = datomsim("info " + path("ends.json"));
  ASSERT_EQ(info.status, 0) << info.output;
  EXPECT_NE(info.output.find("components  4"), std::string::npos) << info.output;
}

TEST_F(BadInput, NumbersThatAreNotFiniteAndSeedsOutOfRangeAreRefused) {
  const std::string run = "run " + box() + " --program flood --root 0,0,0 ";
  refused(run + "--delay-ms nan", "--delay-ms nan: a finite number of milliseconds, 0 or more");
  refused(run + "--jitter-ms inf", "--jitter-ms inf: a finite number of milliseconds, 0 or more");
  refused(run + "--until -1", "--until -1: a finite number of seconds, above 0");
  refused(run + "--seed 99999999999999999999999",
          "--seed \"99999999999999999999999\" must be an integer from 0 to 18446744073709551615");
  refused(run + "--seed -1", "--seed \"-1\" must be an integer");
  refused("geometry --radius 1e308", "radius must lie between 1e-12 and 1e12, got 1e+308");
  refused("geometry --radius nan", "--radius: must be a finite number, got nan");
  refused("generate random --count 5 --seed 1e3 -o " + path("r.json"), "--seed \"1e3\"",
          path("r.json"));
}

TEST_F(BadInput, AnOutputThatWouldOverwriteAnInputOrAnotherOutputIsRefused) {
  const std::string scene = box();
  const std::string before = readText(scene);
  refused("reach " + scene + " --goal 0,0,2 --out " + scene,
          "--out " + scene + " would overwrite the scene it reads");
  refused("run " + scene + " --program flood --root 0,0,0 --trace " + scene,
          "--trace " + scene + " would overwrite the scene it reads");
  refused(
      "run " + scene + " --program flood --root 0,0,0 --trace " + path("x") + " --out " + path("x"),
      "--out and --trace both name", path("x"));
  refused("run " + scene + " --program flood --root 0,0,0 --trace -",
          "--out and --trace would both write to standard output");
  refused("convert " + scene + " -o " + path(".") + "/box.json", "would overwrite the scene");
  refused("generate box --size 2,2,2 -o " + path("t.json") + " --target " + path("t.json"),
          "would overwrite the --target it reads");
  refused("reach " + scene + " --goal 0,0,2 --png " + path("p.png") + " --svg " + path("./p.png"),
          "--png and --svg both name", path("p.png"));
  EXPECT_EQ(readText(scene), before);
}

// CLI11's own checks printed their range up to the largest double (309 digits), and sscanf wrapped
// a frame size beyond int into another number.
TEST_F(BadInput, NumbersOutOfRangeAreNamedInOneShortSentence) {
  refused("generate random --count 0 -o " + path("r.json"),
          "--count: must be an integer >= 1, got 0", path("r.json"));
  refused("generate random --height 0 -o " + path("r.json"),
          "--height: must be an integer >= 1, got 0", path("r.json"));
  refused("generate random --count 1.5 -o " + path("r.json"),
          "--count: must be an integer >= 1, got 1.5", path("r.json"));
  refused("reach " + box() + " --goal 1,1,2 --max-size -1 --png " + path("m.png"),
          "--max-size: must be an integer >= 0, got -1", path("m.png"));
  refused("video " + box() + " --size 99999999999x180 -o " + path("v.gif"),
          "--size 99999999999x180: write WIDTHxHEIGHT in pixels", path("v.gif"));
  for (const std::string& command :
       std::vector<std::string>{"generate random --count 0", "generate random --height 0",
                                "reach " + box() + " --goal 1,1,2 --max-size -1"}) {
    EXPECT_LT(datomsim(command).output.size(), 200u) << command;
  }
}

TEST_F(BadInput, CommandLineMistakesExitOneAndAnUnknownSubcommandIsNamed) {
  refused("rnu " + box(), "unknown subcommand \"rnu\"; did you mean \"run\"?");
  refused("frobnicate", "unknown subcommand \"frobnicate\"; the subcommands are geometry,");
  refused("", "A subcommand is required");
  refused("info --bogus " + box(), "unknown option --bogus for info");
  refused("run " + box(), "--program is required");
  // A mistyped option is named, with the nearest one, before what else is missing.
  refused("run " + box() + " --tiemout 5",
          "unknown option --tiemout for run; did you mean --timeout?");
  refused("generate box --szie 2,2,2 -o " + path("b.json"),
          "unknown option --szie for generate box; did you mean --size?", path("b.json"));
  refused("actuators show sma-spring --sise=1cm",
          "unknown option --sise for actuators show; did you mean --size?");
  refused("loads " + box() + " --latch-forc 1",
          "unknown option --latch-forc for loads; did you mean --latch-force?");
  EXPECT_EQ(datomsim("--version").status, 0);
  EXPECT_EQ(datomsim("run --help").status, 0);
}

}  // namespace
}  // namespace datomsim
