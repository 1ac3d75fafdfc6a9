#include "video/child_process.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>
#include <cerrno>
#include <cstdlib>
#include <cstring>

extern char** environ;

namespace datomsim::video {

namespace {

struct Pipe {
  int read = -1;
  int write = -1;
};

// A pipe whose ends close on exec: the child gets only the ends dup2 gives it.
Result<Pipe> makePipe() {
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0) return Error{fmt::format("pipe: {}", std::strerror(errno))};
  return Pipe{ends[0], ends[1]};
}

void closeIfOpen(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

}  // namespace

std::filesystem::path findExecutable(const std::string& executable) {
  if (executable.empty()) return {};
  if (executable.find('/') != std::string::npos) {
    return ::access(executable.c_str(), X_OK) == 0 ? std::filesystem::path(executable)
                                                   : std::filesystem::path();
  }
  const char* path = std::getenv("PATH");
  std::string_view directories = path != nullptr ? path : "/usr/local/bin:/usr/bin:/bin";
  while (!directories.empty()) {
    const size_t colon = directories.find(':');
    const std::string_view directory = directories.substr(0, colon);
    directories = colon == std::string_view::npos ? "" : directories.substr(colon + 1);
    if (directory.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(directory) / executable;
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error) &&
        ::access(candidate.c_str(), X_OK) == 0) {
      return candidate;
    }
  }
  return {};
}

Result<ChildProcess> ChildProcess::start(const std::vector<std::string>& argv,
                                         const ChildOptions& options) {
  if (argv.empty()) return Error{"no program to start"};
  const std::filesystem::path program = findExecutable(argv[0]);
  if (program.empty())
    return Error{fmt::format("{} is not installed (not found in PATH)", argv[0])};

  ChildProcess child;
  Pipe input, commands, replies;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const auto fail = [&](const std::string& what) -> Result<ChildProcess> {
    posix_spawn_file_actions_destroy(&actions);
    for (int* fd : {&input.read, &input.write, &commands.read, &commands.write, &replies.read,
                    &replies.write}) {
      closeIfOpen(*fd);
    }
    return Error{fmt::format("cannot start {}: {}", argv[0], what)};
  };
  if (options.pipeInput) {
    auto made = makePipe();
    if (!made) return fail(made.error());
    input = *made;
    posix_spawn_file_actions_adddup2(&actions, input.read, STDIN_FILENO);
  } else {
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  }
  if (options.devtoolsPipes) {
    auto toChild = makePipe();
    if (!toChild) return fail(toChild.error());
    commands = *toChild;
    auto fromChild = makePipe();
    if (!fromChild) return fail(fromChild.error());
    replies = *fromChild;
    posix_spawn_file_actions_adddup2(&actions, commands.read, 3);
    posix_spawn_file_actions_adddup2(&actions, replies.write, 4);
  }
  const std::string log = options.log.empty() ? "/dev/null" : options.log.string();
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);

  std::vector<char*> arguments;
  for (const std::string& argument : argv) arguments.push_back(const_cast<char*>(argument.c_str()));
  arguments.push_back(nullptr);
  const int spawned =
      ::posix_spawn(&child.pid_, program.c_str(), &actions, nullptr, arguments.data(), environ);
  if (spawned != 0) return fail(std::strerror(spawned));
  posix_spawn_file_actions_destroy(&actions);

  // The child holds its ends now; this process keeps the others.
  closeIfOpen(input.read);
  closeIfOpen(commands.read);
  closeIfOpen(replies.write);
  child.input_ = input.write;
  child.commands_ = commands.write;
  child.replies_ = replies.read;
  return child;
}

ChildProcess::ChildProcess(ChildProcess&& other) noexcept
    : pid_(other.pid_), input_(other.input_), commands_(other.commands_), replies_(other.replies_) {
  other.pid_ = -1;
  other.input_ = other.commands_ = other.replies_ = -1;
}

ChildProcess::~ChildProcess() {
  if (pid_ > 0) kill();
  closeAll();
}

void ChildProcess::closeAll() {
  closeIfOpen(input_);
  closeIfOpen(commands_);
  closeIfOpen(replies_);
}

Status ChildProcess::writeInput(std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(input_, bytes.data(), bytes.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      return Error{std::strerror(errno)};
    }
    bytes.remove_prefix(size_t(written));
  }
  return Ok{};
}

void ChildProcess::closeInput() {
  closeIfOpen(input_);
}

int ChildProcess::wait() {
  closeAll();
  if (pid_ <= 0) return -1;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0) {
    if (errno != EINTR) {
      pid_ = -1;
      return -1;
    }
  }
  pid_ = -1;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

void ChildProcess::kill() {
  if (pid_ > 0) ::kill(pid_, SIGKILL);
  wait();
}

}  // namespace datomsim::video
