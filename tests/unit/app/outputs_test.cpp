// A command's files as a user meets them (docs/limits.md, "Files"): no output overwrites any input
// of the command, a special file is written into or refused (never replaced), a failed command
// leaves every existing file as it was and no new one, pictures are bounded before they are drawn,
// and inputs are read up to a bound.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "command_line.h"
#include "support/temporary_directory.h"

namespace datomsim {
namespace {

namespace fs = std::filesystem;
using testing::readText;

class Outputs : public CommandLine {
 protected:
  // Two modules a million cells apart: a picture of them is millions of pixels wide.
  std::string farApart() {
    const std::string file = path("far.json");
    testing::writeText(file,
                       R"({"format":"datomsim-scene","version":1,"name":"far","grid":null,)"
                       R"("blockSize":[10,10,10],"modules":[)"
                       R"({"id":1,"cell":[0,0,0],"orientation":0,"color":[128,128,128]},)"
                       R"({"id":2,"cell":[1000000,0,0],"orientation":0,"color":[128,128,128]}]})");
    return file;
  }
  std::string reachOptions() { return " --goal 6,5,2 --start 0,0,2"; }
  // A viewer script of its own: the build may have none.
  std::string viewerScript() {
    testing::writeText(path("viewer.js"), "// a viewer\n");
    return " --viewer-js " + path("viewer.js");
  }
};

// --- outputs over inputs ---

TEST_F(Outputs, CompareRefusesToWriteItsSummaryOverItsOwnScene) {
  const std::string dir = path("cmp");
  fs::create_directories(dir);
  const std::string scene = dir + "/compare.json";
  fs::copy_file(arch(1), scene);
  const std::string before = readText(scene);
  const Outcome outcome = datomsim("compare " + scene + reachOptions() + " -o " + dir);
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("would overwrite the scene it reads"), std::string::npos)
      << outcome.output;
  EXPECT_EQ(readText(scene), before);
  EXPECT_FALSE(fs::exists(dir + "/datom-reach.json"));
  EXPECT_FALSE(fs::exists(dir + "/compare.png"));
}

TEST_F(Outputs, ViewRefusesToWriteItsPageOverTheReachMapItShows) {
  const std::string scene = arch(1);
  const std::string map = path("r.json");
  ASSERT_EQ(datomsim("reach " + scene + reachOptions() + " --out " + map).status, 0);
  const std::string before = readText(map);
  const Outcome outcome =
      datomsim("view " + scene + " --reach " + map + " -o " + map + viewerScript());
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("would overwrite the --reach it reads"), std::string::npos)
      << outcome.output;
  EXPECT_EQ(readText(map), before);
}

TEST_F(Outputs, ViewRefusesToWriteItsPageOverTheViewerScriptItInlines) {
  const std::string script = path("v.js");
  testing::writeText(script, "// a viewer\n");
  const Outcome outcome = datomsim("view " + arch(1) + " -o " + script + " --viewer-js " + script);
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("would overwrite the --viewer-js it reads"), std::string::npos)
      << outcome.output;
  EXPECT_EQ(readText(script), "// a viewer\n");
}

TEST_F(Outputs, AnOutputThroughASymlinkToAnInputIsRefused) {
  const std::string scene = arch(1);
  const std::string link = path("link.json");
  fs::create_symlink(scene, link);
  const std::string before = readText(scene);
  const Outcome outcome = datomsim("reach " + scene + reachOptions() + " --out " + link);
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_EQ(readText(scene), before);
  EXPECT_TRUE(fs::is_symlink(link));
}

// --- special files ---

TEST_F(Outputs, AnOutputThroughASymlinkToADeviceIsWrittenIntoNotReplaced) {
  const std::string link = path("null");
  fs::create_symlink("/dev/null", link);
  const Outcome outcome = datomsim("reach " + arch(1) + reachOptions() + " --out " + link);
  EXPECT_EQ(outcome.status, 0) << outcome.output;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST_F(Outputs, AnOutputOnAFifoNobodyReadsIsRefusedWithoutWaiting) {
  const std::string fifo = path("fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const Outcome outcome = shell("timeout 60 " + std::string(DATOMSIM_BINARY) + " reach " + arch(1) +
                                reachOptions() + " --out " + fifo + " 2>&1");
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("no process reads it"), std::string::npos) << outcome.output;
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST_F(Outputs, AnOutputOnAFifoIsWrittenIntoWhenSomeoneReads) {
  const std::string fifo = path("fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  const Outcome outcome = datomsim("reach " + arch(1) + reachOptions() + " --out " + fifo);
  EXPECT_EQ(outcome.status, 0) << outcome.output;
  std::string got(65536, '\0');
  const ssize_t read = ::read(reader, got.data(), got.size());
  ::close(reader);
  ASSERT_GT(read, 0);
  got.resize(size_t(read));
  EXPECT_NE(got.find("\"distances\""), std::string::npos) << got.substr(0, 200);
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST_F(Outputs, AnOutputNamingTheFileStandardOutputGoesToIsWrittenAsStandardOutput) {
  // Appended, as the shell opened it: not replaced by a new file of the JSON alone.
  const std::string log = path("log.txt");
  testing::writeText(log, "old\n");
  const Outcome outcome = shell(std::string(DATOMSIM_BINARY) + " reach " + arch(1) +
                                reachOptions() + " --out /dev/stdout >> " + log);
  EXPECT_EQ(outcome.status, 0) << outcome.output;
  const std::string text = readText(log);
  EXPECT_EQ(text.rfind("old\n{\"goal\"", 0), 0u) << text.substr(0, 100);
}

TEST_F(Outputs, ADirectoryAsAnOutputIsRefused) {
  const Outcome outcome = datomsim("reach " + arch(1) + reachOptions() + " --out " + path(""));
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("is a directory"), std::string::npos) << outcome.output;
}

// --- a failed command leaves nothing ---

TEST_F(Outputs, RunWhoseOutIsADirectoryFailsBeforeRunningAndWritesNoTrace) {
  const std::string dir = path("d");
  fs::create_directories(dir);
  const Outcome outcome = datomsim("run " + arch(1) +
                                   " --program follow-gradient --goal 6,5,2 --start 0,0,2 "
                                   "--trace " +
                                   path("t.jsonl") + " --out " + dir);
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("is a directory"), std::string::npos) << outcome.output;
  EXPECT_FALSE(fs::exists(path("t.jsonl")));
}

TEST_F(Outputs, ReachWhoseSvgIsADirectoryLeavesItsPngAsItWas) {
  fs::create_directories(path("d.svg"));
  testing::writeText(path("o.png"), "old");
  const Outcome outcome = datomsim("reach " + arch(1) + reachOptions() + " --png " + path("o.png") +
                                   " --svg " + path("d.svg"));
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_EQ(readText(path("o.png")), "old");
}

TEST_F(Outputs, CompareWhoseSummaryIsADirectoryChangesNothing) {
  const std::string dir = path("cmp");
  fs::create_directories(dir + "/compare.json");
  testing::writeText(dir + "/compare.png", "old");
  const Outcome outcome = datomsim("compare " + arch(1) + reachOptions() + " -o " + dir);
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_EQ(readText(dir + "/compare.png"), "old");
  EXPECT_FALSE(fs::exists(dir + "/datom-reach.json"));
  EXPECT_FALSE(fs::exists(dir + "/catom3d-reach.json"));
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "compare.json" || name == "compare.png") << name << " was left behind";
  }
}

TEST_F(Outputs, CompareThatFailsRemovesTheDirectoryItMade) {
  const std::string dir = path("new/cmp");
  const Outcome outcome = datomsim("compare " + arch(1) + " --goal 600,5,2 -o " + dir);
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_FALSE(fs::exists(path("new")));
}

TEST_F(Outputs, AnUnwritableDirectoryIsRefusedBeforeAnythingIsWritten) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes into any directory";
  const std::string dir = path("locked");
  fs::create_directories(dir);
  fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
  const Outcome outcome = datomsim("reach " + arch(1) + reachOptions() + " --png " + path("o.png") +
                                   " --out " + dir + "/r.json");
  fs::permissions(dir, fs::perms::owner_all);
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_FALSE(fs::exists(path("o.png")));
}

// --- pictures ---

TEST_F(Outputs, APictureTooWideIsRefusedBeforeItIsDrawn) {
  const std::string scene = farApart();
  for (const std::string& options :
       {"--svg " + path("f.svg"), "--svg " + path("f.svg") + " --max-size 0",
        "--svg " + path("f.svg") + " --scale 48", "--png " + path("f.png")}) {
    const Outcome outcome = datomsim("reach " + scene + " --goal 1,0,0 " + options);
    EXPECT_EQ(outcome.status, 1) << options << "\n" << outcome.output;
    EXPECT_NE(outcome.output.find("more than the 32767 pixels a picture may have on a side"),
              std::string::npos)
        << options << "\n"
        << outcome.output;
    EXPECT_FALSE(fs::exists(path("f.svg")));
    EXPECT_FALSE(fs::exists(path("f.png")));
  }
}

TEST_F(Outputs, ASafetyMapTooWideIsRefusedBeforeItIsDrawn) {
  const std::string scene = farApart();
  for (const std::string& picture : {path("l.svg"), path("l.png")}) {
    const std::string option = picture.ends_with(".svg") ? " --svg " : " --png ";
    const Outcome outcome = datomsim("loads " + scene + option + picture);
    EXPECT_EQ(outcome.status, 1) << outcome.output;
    EXPECT_NE(outcome.output.find("more than the 32767 pixels a picture may have on a side"),
              std::string::npos)
        << outcome.output;
    EXPECT_FALSE(fs::exists(picture));
  }
}

// --- inputs ---

TEST_F(Outputs, ViewRefusesADeviceAsAnyOfItsInputs) {
  const std::string scene = arch(1);
  for (const std::string& arguments :
       {"/dev/zero" + viewerScript(), scene + " --reach /dev/zero" + viewerScript(),
        scene + " --viewer-js /dev/zero"}) {
    const Outcome outcome = shell("timeout 60 " + std::string(DATOMSIM_BINARY) + " view " +
                                  arguments + " -o " + path("v.html") + " 2>&1");
    EXPECT_EQ(outcome.status, 1) << arguments << "\n" << outcome.output;
    EXPECT_NE(outcome.output.find("/dev/zero: not a regular file"), std::string::npos)
        << arguments << "\n"
        << outcome.output;
    EXPECT_FALSE(fs::exists(path("v.html")));
  }
}

TEST_F(Outputs, ViewRefusesAnInputLargerThanItsBoundWithoutReadingIt) {
  const std::string big = path("big.js");
  { std::ofstream(big) << "x"; }
  fs::resize_file(big, (size_t{512} << 20) + 1);  // sparse: nothing is written
  const Outcome outcome = datomsim("view " + arch(1) + " --viewer-js " + big);
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("more than the 512 MiB"), std::string::npos) << outcome.output;
}

// A reader that quits mid-write (head -c 10) ends the command with a message naming the output and
// status 1, not with SIGPIPE (status 141 through the shell); through a pipe and through a FIFO.
TEST_F(Outputs, AReaderThatQuitsMidWriteIsAnErrorNamingTheOutput) {
  const std::string binary = DATOMSIM_BINARY;
  const auto read = [&](const std::string& name) {
    std::ifstream in(path(name));
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  ASSERT_EQ(shell(binary + " -q generate box --size 80,80,1 -o " + path("b.json")).status, 0);
  // The map is 84 kB, more than a pipe holds: the writer meets the closed end.
  shell("{ " + binary + " reach " + path("b.json") + " --goal 0,0,1 2>" + path("errors") +
        "; echo $? >" + path("status") + "; } | head -c 10");
  EXPECT_EQ(read("status"), "1\n");
  EXPECT_NE(read("errors").find("cannot write to standard output"), std::string::npos)
      << read("errors");

  ASSERT_EQ(::mkfifo(path("fifo").c_str(), 0600), 0);
  const Outcome outcome =
      shell("(head -c 10 " + path("fifo") + " >/dev/null &) && sleep 0.2 && " + binary + " reach " +
            path("b.json") + " --goal 0,0,1 --out " + path("fifo"));
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("cannot write " + path("fifo")), std::string::npos)
      << outcome.output;
}

}  // namespace
}  // namespace datomsim
