#include "common/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

namespace datomsim {
namespace {

std::string systemError(int code) {
  return std::strerror(code);
}

// Distinguishes temporary files of several writers in one process (threads, parallel tests);
// the process id distinguishes processes.
std::atomic<unsigned> temporaryCounter{0};

}  // namespace

Status writeFileAtomically(const std::filesystem::path& target,
                           const std::function<Status(std::FILE*)>& write) {
  const std::string name = target.string();
  if (!target.has_filename()) return Error{"cannot write " + name + ": not a file name"};
  const std::filesystem::path directory =
      target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");

  // Create the temporary file with O_EXCL so that we never clobber someone else's file. Hidden
  // (leading dot) so that a crash before the rename leaves at most a dot file.
  std::filesystem::path temporary;
  int fd = -1;
  for (int attempt = 0; fd < 0; ++attempt) {
    std::string temporaryName = ".";
    temporaryName += target.filename().string();
    temporaryName += ".tmp-";
    temporaryName += std::to_string(::getpid());
    temporaryName += '-';
    temporaryName += std::to_string(temporaryCounter.fetch_add(1));
    temporary = directory / temporaryName;
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && (errno != EEXIST || attempt > 100)) {
      return Error{"cannot write " + name + ": cannot create a temporary file in " +
                   directory.string() + ": " + systemError(errno)};
    }
  }
  std::FILE* file = ::fdopen(fd, "wb");
  if (!file) {
    const int code = errno;
    ::close(fd);
    ::unlink(temporary.c_str());
    return Error{"cannot write " + name + ": " + systemError(code)};
  }

  // Write, flush and sync; the first failure wins, and the temporary file goes away.
  Status status = write(file);
  if (status.ok() && (std::fflush(file) != 0 || std::ferror(file))) {
    status = Error{"cannot write " + name + ": " + systemError(errno)};
  }
  // Without fsync a crash soon after the rename can leave an empty file under the target's name.
  if (status.ok() && ::fsync(::fileno(file)) != 0) {
    status = Error{"cannot write " + name + ": " + systemError(errno)};
  }
  if (std::fclose(file) != 0 && status.ok()) {
    status = Error{"cannot write " + name + ": " + systemError(errno)};
  }
  if (!status.ok()) {
    ::unlink(temporary.c_str());
    return status;
  }
  if (std::rename(temporary.c_str(), target.c_str()) != 0) {
    const int code = errno;
    ::unlink(temporary.c_str());
    return Error{"cannot write " + name + ": " + systemError(code)};
  }
  return Ok{};
}

Status writeFileAtomically(const std::filesystem::path& target, std::string_view bytes) {
  return writeFileAtomically(target, [&](std::FILE* file) -> Status {
    if (std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size()) {
      return Error{"cannot write " + target.string() + ": " + systemError(errno)};
    }
    return Ok{};
  });
}

}  // namespace datomsim
