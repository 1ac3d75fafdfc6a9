#include "common/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace datomsim {
namespace {

namespace fs = std::filesystem;

// A fresh empty directory per test, removed afterwards.
class AtomicBytes : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = fs::temp_directory_path() / (std::string("datomsim_atomic_file_") + info->name() +
                                              "_" + std::to_string(::getpid()));
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  static std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
  }

  size_t entries() const {
    return static_cast<size_t>(std::distance(fs::directory_iterator(directory_), {}));
  }

  fs::path directory_;
};

TEST_F(AtomicBytes, WritesTheBytesReadableByAll) {
  const fs::path path = directory_ / "a.bin";
  const std::string bytes("one\0two", 7);
  ASSERT_TRUE(writeFileAtomically(path, bytes).ok());
  EXPECT_EQ(contents(path), bytes);
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::others_read, fs::perms::others_read);
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicBytes, ReplacesAnExistingFile) {
  const fs::path path = directory_ / "a.txt";
  ASSERT_TRUE(writeFileAtomically(path, "a much longer first version").ok());
  ASSERT_TRUE(writeFileAtomically(path, "second").ok());
  EXPECT_EQ(contents(path), "second");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicBytes, RefusesAMissingDirectoryNamingThePath) {
  const fs::path path = directory_ / "missing" / "a.txt";
  const Status status = writeFileAtomically(path, "x");
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().find(path.string()), std::string::npos) << status.error();
  EXPECT_NE(status.error().find("No such file or directory"), std::string::npos);
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(AtomicBytes, LeavesNoTemporaryFileWhenTheRenameFails) {
  // A directory cannot be replaced by a file: the rename fails after the bytes are written.
  const fs::path path = directory_ / "taken";
  fs::create_directory(path);
  const Status status = writeFileAtomically(path, "x");
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().find(path.string()), std::string::npos) << status.error();
  EXPECT_TRUE(fs::is_directory(path));
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicBytes, RefusesAPathWithoutAFileName) {
  const Status status = writeFileAtomically(directory_ / "", "x");
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().find("not a file name"), std::string::npos) << status.error();
  EXPECT_EQ(entries(), 0u);
}

}  // namespace
}  // namespace datomsim
