// Running the datomsim binary as a user does, for the command-line tests.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

#include "support/temporary_directory.h"

namespace datomsim {

struct Outcome {
  int status = -1;
  std::string output;  // standard output and standard error together
};

// Runs one line through the shell (/bin/sh), as a user types it.
inline Outcome shell(const std::string& line) {
  const std::string command = line + " 2>&1";
  Outcome outcome;
  FILE* pipe = ::popen(command.c_str(), "r");
  std::array<char, 4096> buffer{};
  size_t read = 0;
  while ((read = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    outcome.output.append(buffer.data(), read);
  }
  const int status = ::pclose(pipe);
  outcome.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

inline Outcome datomsim(const std::string& arguments) {
  return shell(std::string(DATOMSIM_BINARY) + " " + arguments);
}

class CommandLine : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (directory_.path() / name).string(); }
  std::string arch(int hole) {
    const std::string file = path("arch" + std::to_string(hole) + ".json");
    EXPECT_EQ(datomsim("generate arch --hole " + std::to_string(hole) + " -o " + file).status, 0);
    return file;
  }
  testing::TemporaryDirectory directory_;
};

}  // namespace datomsim
