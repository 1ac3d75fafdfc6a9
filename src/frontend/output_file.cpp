#include "frontend/output_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "frontend/usage_error.h"

namespace datomsim::frontend {

namespace fs = std::filesystem;

struct CommandFiles::Output {
  enum class Kind { kStandardOutput, kFile, kStream };
  std::string option, path;  // as given
  Kind kind = Kind::kFile;
  fs::path target;            // kFile: the file the partial file replaces (a symlink followed)
  fs::path partial;           // kFile: the hidden file written meanwhile
  std::FILE* file = nullptr;  // kFile: the partial file, open
  int fd = -1;                // kStream: the device or FIFO, open
  std::string held;           // kStandardOutput, kStream: what commit() writes
  std::string holds;          // for the "wrote" line
  bool written = false;

  ~Output() {
    if (file != nullptr) std::fclose(file);
    if (!partial.empty()) ::unlink(partial.c_str());
    if (fd >= 0) ::close(fd);
  }
};

namespace {

bool isStandardOutput(const std::string& path) {
  return path.empty() || path == "-";
}

std::optional<struct stat> statOf(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) return std::nullopt;
  return status;
}

// Whether two paths name the same file: the same device and inode when both exist (through any
// symlink or hard link), else the same absolute path with its symlinks resolved.
bool sameFile(const std::string& a, const std::string& b) {
  const auto statA = statOf(a), statB = statOf(b);
  if (statA && statB) return statA->st_dev == statB->st_dev && statA->st_ino == statB->st_ino;
  std::error_code error;
  // absolute() first: weakly_canonical leaves a relative path with no existing part relative.
  const fs::path absoluteA = fs::weakly_canonical(fs::absolute(a), error);
  if (error) return false;
  const fs::path absoluteB = fs::weakly_canonical(fs::absolute(b), error);
  return !error && absoluteA == absoluteB;
}

// Standard output by name, or a file that is standard output's own (/dev/stdout, /dev/fd/1, or
// the file it is redirected to).
bool writesStandardOutput(const std::string& path) {
  if (isStandardOutput(path)) return true;
  struct stat out {};
  const auto status = statOf(path);
  return status && ::fstat(STDOUT_FILENO, &out) == 0 && status->st_dev == out.st_dev &&
         status->st_ino == out.st_ino && !S_ISCHR(out.st_mode);
}

}  // namespace

void refuseClashes(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    const NamedPath& output = outputs[i];
    if (writesStandardOutput(output.path)) {
      for (size_t k = 0; k < i; ++k) {
        if (writesStandardOutput(outputs[k].path)) {
          throw UsageError(
              fmt::format("{} and {} would both write to standard output; give one of them a file",
                          outputs[k].option, output.option));
        }
      }
      if (isStandardOutput(output.path)) continue;
    }
    for (const NamedPath& input : inputs) {
      if (!isStandardOutput(input.path) && sameFile(input.path, output.path)) {
        throw UsageError(fmt::format("{} {} would overwrite the {} it reads; choose another file",
                                     output.option, output.path, input.option));
      }
    }
    for (size_t k = 0; k < i; ++k) {
      if (!isStandardOutput(outputs[k].path) && sameFile(outputs[k].path, output.path)) {
        throw UsageError(fmt::format("{} and {} both name {}; choose two files", outputs[k].option,
                                     output.option, output.path));
      }
    }
  }
}

namespace {

// Distinguishes partial files of several writers in one process (threads, Python); the process
// id distinguishes processes.
std::atomic<unsigned> partialCounter{0};

std::string systemError() {
  return std::strerror(errno);
}

// Opens a device or a FIFO to write into. A FIFO is opened without waiting: with no reader the
// open fails (ENXIO) rather than block, and the output is refused.
int openStream(const CommandFiles::Output& output, bool fifo) {
  const int fd =
      ::open(output.path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | (fifo ? O_NONBLOCK : 0));
  if (fd < 0 && fifo && errno == ENXIO) {
    throw UsageError(fmt::format("{} {}: a FIFO, and no process reads it; start its reader first",
                                 output.option, output.path));
  }
  if (fd < 0) {
    throw UsageError(
        fmt::format("{} {}: cannot write: {}", output.option, output.path, systemError()));
  }
  // Written into once open, waiting for the reader as a pipe does.
  if (fifo) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  return fd;
}

// The file a partial file replaces: the path, or what its symlinks name.
fs::path fileTarget(const CommandFiles::Output& output, bool exists) {
  if (exists) {
    std::error_code error;
    const fs::path resolved = fs::canonical(output.path, error);
    if (!error) return resolved;
  }
  struct stat link {};
  if (!exists && ::lstat(output.path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
    throw UsageError(fmt::format("{} {}: a symlink to a file that does not exist; name the file",
                                 output.option, output.path));
  }
  return output.path;
}

void openPartial(CommandFiles::Output& output) {
  const fs::path& target = output.target;
  if (!target.has_filename()) {
    throw UsageError(fmt::format("{} {}: is a directory; name a file", output.option, output.path));
  }
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const auto where = statOf(directory.string());
  if (!where) {
    throw UsageError(
        fmt::format("{} {}: no directory {}", output.option, output.path, directory.string()));
  }
  if (!S_ISDIR(where->st_mode)) {
    throw UsageError(fmt::format("{} {}: {} is not a directory", output.option, output.path,
                                 directory.string()));
  }
  // Hidden, and made with O_EXCL so that nobody else's file is ever written.
  int fd = -1;
  for (int attempt = 0; fd < 0; ++attempt) {
    output.partial = directory / fmt::format(".{}.partial-{}-{}", target.filename().string(),
                                             ::getpid(), partialCounter.fetch_add(1));
    fd = ::open(output.partial.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && (errno != EEXIST || attempt > 100)) {
      output.partial.clear();
      throw UsageError(fmt::format("{} {}: cannot write in {}: {}", output.option, output.path,
                                   directory.string(), systemError()));
    }
  }
  output.file = ::fdopen(fd, "wb");
  if (output.file == nullptr) {
    ::close(fd);
    throw UsageError(
        fmt::format("{} {}: cannot write: {}", output.option, output.path, systemError()));
  }
}

void open(CommandFiles::Output& output) {
  using Kind = CommandFiles::Output::Kind;
  // Standard output's own file too (/dev/stdout redirected to a file, with >> say), written as
  // standard output: a new file renamed onto it would drop what the shell set up.
  if (writesStandardOutput(output.path)) {
    output.kind = Kind::kStandardOutput;
    return;
  }
  const auto status = statOf(output.path);
  if (!status && errno != ENOENT) {
    throw UsageError(fmt::format("{} {}: {}", output.option, output.path, systemError()));
  }
  if (status && S_ISDIR(status->st_mode)) {
    throw UsageError(fmt::format("{} {}: is a directory; name a file", output.option, output.path));
  }
  if (status && (S_ISCHR(status->st_mode) || S_ISFIFO(status->st_mode))) {
    output.kind = Kind::kStream;
    output.fd = openStream(output, S_ISFIFO(status->st_mode));
    return;
  }
  if (status && !S_ISREG(status->st_mode)) {
    throw UsageError(
        fmt::format("{} {}: neither a file, a character device nor a FIFO; choose a file",
                    output.option, output.path));
  }
  output.kind = Kind::kFile;
  output.target = fileTarget(output, status.has_value());
  openPartial(output);
}

// Writes all of `bytes` to `fd`; false on an error.
bool writeAll(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    bytes.remove_prefix(size_t(written));
  }
  return true;
}

}  // namespace

CommandFiles::CommandFiles(const std::vector<NamedPath>& inputs,
                           const std::vector<NamedPath>& outputs, const fs::path& directory,
                           const std::string& directoryOption) {
  refuseClashes(inputs, outputs);
  try {
    makeDirectory(directory, directoryOption);
    for (const NamedPath& named : outputs) {
      auto output = std::make_unique<Output>();
      output->option = named.option;
      output->path = named.path;
      outputs_.push_back(std::move(output));
      open(*outputs_.back());
    }
  } catch (...) {
    // No destructor runs for an object not made: undo here what the outputs before did.
    undo();
    throw;
  }
}

void CommandFiles::makeDirectory(const fs::path& directory, const std::string& option) {
  if (directory.empty()) return;
  std::error_code error;
  if (fs::exists(directory, error) && !fs::is_directory(directory, error)) {
    throw UsageError(fmt::format("{} {}: is a file, not a directory", option, directory.string()));
  }
  // Made from the outermost missing one, so that a failure removes exactly those.
  std::vector<fs::path> missing;
  for (fs::path level = directory; !level.empty() && !fs::exists(level, error);
       level = level.parent_path()) {
    missing.insert(missing.begin(), level);
    if (level == level.parent_path()) break;
  }
  for (const fs::path& level : missing) {
    if (::mkdir(level.c_str(), 0777) != 0 && errno != EEXIST) {
      throw UsageError(fmt::format("{} {}: cannot make {}: {}", option, directory.string(),
                                   level.string(), systemError()));
    }
    madeDirectories_.push_back(level);
  }
}

void CommandFiles::undo() {
  written_.clear();
  outputs_.clear();  // closes and removes the partial files
  for (auto level = madeDirectories_.rbegin(); level != madeDirectories_.rend(); ++level) {
    ::rmdir(level->c_str());  // only when empty
  }
  madeDirectories_.clear();
}

CommandFiles::~CommandFiles() {
  if (!committed_) undo();
}

CommandFiles::Output& CommandFiles::find(const std::string& name) {
  Output* found = nullptr;
  size_t named = 0;
  for (const auto& output : outputs_) {
    if (output->option == name) found = output.get(), ++named;
  }
  if (named == 1) return *found;
  // Outputs of one option (a directory's files) by their path.
  for (const auto& output : outputs_) {
    if (output->path == name) return *output;
  }
  throw std::logic_error("CommandFiles: no output " + name);
}

void CommandFiles::write(const std::string& name, const std::function<Status(std::FILE*)>& write) {
  Output& output = find(name);
  const std::string shown =
      output.kind == Output::Kind::kStandardOutput ? std::string("standard output") : output.path;
  if (output.kind == Output::Kind::kFile) {
    const Status status = write(output.file);
    if (!status) check(Error{fmt::format("cannot write {}: {}", shown, status.error())});
    if (std::fflush(output.file) != 0 || std::ferror(output.file) != 0) {
      throw UsageError(fmt::format("cannot write {}: {}", shown, systemError()));
    }
  } else {
    char* bytes = nullptr;
    size_t size = 0;
    std::FILE* memory = ::open_memstream(&bytes, &size);
    if (memory == nullptr) throw std::bad_alloc();
    const Status status = write(memory);
    std::fclose(memory);
    output.held.assign(bytes, size);
    std::free(bytes);
    if (!status) check(Error{fmt::format("cannot write {}: {}", shown, status.error())});
  }
  if (!output.written) written_.push_back(&output);
  output.written = true;
}

void CommandFiles::write(const std::string& name, std::string_view text) {
  write(name, [&](std::FILE* file) -> Status {
    if (std::fwrite(text.data(), 1, text.size(), file) != text.size()) return Error{systemError()};
    return Ok{};
  });
}

void CommandFiles::describe(const std::string& name, std::string holds) {
  find(name).holds = std::move(holds);
}

void CommandFiles::commit(const Reporter& reporter) {
  // Every partial file complete on disk first (without fsync a crash soon after the rename can
  // leave an empty file under the output's name), then all renamed at once.
  for (Output* output : written_) {
    if (output->kind != Output::Kind::kFile) continue;
    const int closed = ::fsync(::fileno(output->file)) == 0 ? std::fclose(output->file) : -1;
    if (closed != 0)
      throw UsageError(fmt::format("cannot write {}: {}", output->path, systemError()));
    output->file = nullptr;
  }
  for (Output* output : written_) {
    if (output->kind != Output::Kind::kFile) continue;
    if (std::rename(output->partial.c_str(), output->target.c_str()) != 0) {
      throw UsageError(fmt::format("cannot write {}: {}", output->path, systemError()));
    }
    output->partial.clear();
  }
  committed_ = true;
  for (Output* output : written_) {
    if (output->kind == Output::Kind::kStandardOutput) {
      if (std::fwrite(output->held.data(), 1, output->held.size(), stdout) != output->held.size() ||
          std::fflush(stdout) != 0) {
        throw UsageError(fmt::format("cannot write to standard output: {}", systemError()));
      }
      continue;
    }
    if (output->kind == Output::Kind::kStream && !writeAll(output->fd, output->held)) {
      throw UsageError(fmt::format("cannot write {}: {}", output->path, systemError()));
    }
    reporter.reportWritten(output->path, output->holds);
  }
}

void refuseMisnamedPictures(const std::string& png, const std::string& svg) {
  for (const auto& [option, path, extension] :
       {std::tuple{"--png", png, ".png"}, std::tuple{"--svg", svg, ".svg"}}) {
    std::string given = fs::path(path).extension().string();
    for (char& c : given) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (!path.empty() && given != extension) {
      throw UsageError(
          fmt::format("{} {}: the picture's file name must end in {}", option, path, extension));
    }
  }
}

}  // namespace datomsim::frontend
