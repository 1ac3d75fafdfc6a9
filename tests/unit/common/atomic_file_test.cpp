#include "common/atomic_file.h"

#include <gtest/gtest.h>

#include <string>

#include "support/temporary_directory.h"

namespace datomsim {
namespace {

using testing::readText;
using testing::TemporaryDirectory;

Status writeText(std::FILE* file, const std::string& text) {
  std::fputs(text.c_str(), file);
  return Ok{};
}

TEST(AtomicFile, WritesAndReplacesAFile) {
  TemporaryDirectory directory;
  const auto target = directory.path() / "out.txt";
  ASSERT_TRUE(writeFileAtomically(target, [](std::FILE* f) { return writeText(f, "one"); }).ok());
  EXPECT_EQ(readText(target), "one");
  ASSERT_TRUE(writeFileAtomically(target, [](std::FILE* f) { return writeText(f, "two"); }).ok());
  EXPECT_EQ(readText(target), "two");
  EXPECT_EQ(directory.fileNames(), (std::vector<std::string>{"out.txt"}));
}

TEST(AtomicFile, LeavesNothingWhenTheWriterFails) {
  TemporaryDirectory directory;
  const auto target = directory.path() / "out.txt";
  const Status status = writeFileAtomically(target, [](std::FILE* f) -> Status {
    EXPECT_TRUE(writeText(f, "half").ok());
    return Error{"the writer gave up"};
  });
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error(), "the writer gave up");
  EXPECT_TRUE(directory.fileNames().empty());
}

TEST(AtomicFile, KeepsTheOldFileWhenTheWriterFails) {
  TemporaryDirectory directory;
  const auto target = directory.path() / "out.txt";
  ASSERT_TRUE(writeFileAtomically(target, [](std::FILE* f) { return writeText(f, "old"); }).ok());
  EXPECT_FALSE(writeFileAtomically(target, [](std::FILE*) -> Status { return Error{"no"}; }).ok());
  EXPECT_EQ(readText(target), "old");
  EXPECT_EQ(directory.fileNames(), (std::vector<std::string>{"out.txt"}));
}

TEST(AtomicFile, RefusesAMissingDirectoryNamingTheTarget) {
  TemporaryDirectory directory;
  const auto target = directory.path() / "missing" / "out.txt";
  const Status status = writeFileAtomically(target, [](std::FILE* f) { return writeText(f, "x"); });
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().rfind("cannot write " + target.string() + ": ", 0), 0u)
      << status.error();
  EXPECT_TRUE(directory.fileNames().empty());
}

TEST(AtomicFile, LeavesNoTemporaryFileWhenTheRenameFails) {
  // The target is a non-empty directory: everything works up to the rename.
  TemporaryDirectory directory;
  const auto target = directory.path() / "taken";
  std::filesystem::create_directories(target / "inside");
  const Status status = writeFileAtomically(target, [](std::FILE* f) { return writeText(f, "x"); });
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(directory.fileNames(), (std::vector<std::string>{"taken"}));
}

TEST(AtomicFile, WritesIntoTheCurrentDirectoryForABareName) {
  TemporaryDirectory directory;
  const auto previous = std::filesystem::current_path();
  std::filesystem::current_path(directory.path());
  const Status status =
      writeFileAtomically("bare.txt", [](std::FILE* f) { return writeText(f, "x"); });
  std::filesystem::current_path(previous);
  ASSERT_TRUE(status.ok()) << status.error();
  EXPECT_EQ(directory.fileNames(), (std::vector<std::string>{"bare.txt"}));
}

}  // namespace
}  // namespace datomsim
