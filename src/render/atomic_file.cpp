#include "render/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace datomsim::render {

namespace {

Error failure(const std::filesystem::path& path, int error) {
  return Error{fmt::format("cannot write {}: {}", path.string(), std::strerror(error))};
}

}  // namespace

Status writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
  if (!path.has_filename()) {
    return Error{fmt::format("cannot write {}: no file name", path.string())};
  }

  // The temporary file sits in the destination's directory, so that the rename stays on one file
  // system and is atomic.
  const std::filesystem::path directory = path.has_parent_path() ? path.parent_path() : ".";
  const std::string pattern =
      (directory / fmt::format(".{}.XXXXXX", path.filename().string())).string();
  std::vector<char> temporary(pattern.begin(), pattern.end());
  temporary.push_back('\0');
  const int fd = ::mkstemp(temporary.data());
  if (fd < 0) return failure(path, errno);

  // Write everything, then make it durable before it takes the destination's name.
  auto abandon = [&](int error) {
    ::close(fd);
    ::unlink(temporary.data());
    return failure(path, error);
  };
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      return abandon(errno);
    }
    written += static_cast<size_t>(n);
  }
  // mkstemp creates the file readable by its owner only; a picture is for everyone to read.
  if (::fchmod(fd, 0644) != 0) return abandon(errno);
  if (::fsync(fd) != 0) return abandon(errno);
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary.data());
    return failure(path, error);
  }
  if (::rename(temporary.data(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.data());
    return failure(path, error);
  }
  return Ok{};
}

}  // namespace datomsim::render
