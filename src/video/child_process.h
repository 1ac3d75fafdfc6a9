// A program run beside datomsim, with pipes to it: Chromium, spoken to over the DevTools protocol
// on its descriptors 3 and 4, and ffmpeg, fed frames on its standard input.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "datomsim/result.h"

namespace datomsim::video {

struct ChildOptions {
  // The child reads its standard input from a pipe this process writes (writeInput).
  bool pipeInput = false;
  // The child reads DevTools commands on descriptor 3 and writes its replies on descriptor 4
  // (Chromium's --remote-debugging-pipe).
  bool devtoolsPipes = false;
  // Where the child's standard output and error go; /dev/null when empty.
  std::filesystem::path log;
};

// The program `executable` found as a shell finds it: a path with a '/' as it is, else the first
// executable file of that name in PATH. Empty when there is none.
std::filesystem::path findExecutable(const std::string& executable);

class ChildProcess {
 public:
  // Starts argv[0] (looked up in PATH) with argv. The error names the program.
  static Result<ChildProcess> start(const std::vector<std::string>& argv,
                                    const ChildOptions& options);

  ChildProcess(ChildProcess&& other) noexcept;
  ChildProcess& operator=(ChildProcess&&) = delete;
  ChildProcess(const ChildProcess&) = delete;
  // A child still running is killed and waited for: nothing outlives the command.
  ~ChildProcess();

  // Writes all of `bytes` to the child's standard input; an error when the child has gone.
  Status writeInput(std::string_view bytes);
  // Ends the child's standard input (an encoder then finishes its file).
  void closeInput();
  // Waits for the child to end: its exit status, or 128 + the signal that ended it.
  int wait();
  // Ends the child at once (SIGKILL) and waits for it.
  void kill();

  // The DevTools pipes, this process's ends: commands are written to `commandsFd`, replies read
  // from `repliesFd`; -1 without devtoolsPipes.
  int commandsFd() const { return commands_; }
  int repliesFd() const { return replies_; }

 private:
  ChildProcess() = default;
  void closeAll();

  pid_t pid_ = -1;
  int input_ = -1;
  int commands_ = -1;
  int replies_ = -1;
};

}  // namespace datomsim::video
