#include "frontend/output_file.h"

#include <fmt/format.h>

#include <cctype>
#include <filesystem>
#include <tuple>

#include "common/atomic_file.h"
#include "frontend/usage_error.h"

namespace datomsim::frontend {

void writeOutput(const std::string& path, const std::string& text, const Reporter& reporter) {
  writeOutput(
      path,
      [&](std::FILE* file) -> Status {
        if (std::fwrite(text.data(), 1, text.size(), file) != text.size()) return Error{""};
        return Ok{};
      },
      reporter);
}

void writeOutput(const std::string& path, const std::function<Status(std::FILE*)>& write,
                 const Reporter& reporter) {
  if (path.empty() || path == "-") {
    if (const Status written = write(stdout); !written) {
      throw UsageError("cannot write to standard output");
    }
    return;
  }
  check(writeFileAtomically(path, [&](std::FILE* file) -> Status {
    if (const Status written = write(file); !written) return Error{"cannot write " + path};
    return Ok{};
  }));
  reporter.reportWritten(path);
}

namespace {

// Whether two paths name the same file: the same file on disk, or the same absolute path when
// the output does not exist yet.
bool sameFile(const std::string& a, const std::string& b) {
  std::error_code error;
  if (std::filesystem::equivalent(a, b, error)) return true;
  // absolute() first: weakly_canonical leaves a relative path with no existing part relative.
  const auto absoluteA = std::filesystem::weakly_canonical(std::filesystem::absolute(a), error);
  if (error) return false;
  const auto absoluteB = std::filesystem::weakly_canonical(std::filesystem::absolute(b), error);
  return !error && absoluteA == absoluteB;
}

bool isStandardOutput(const std::string& path) {
  return path.empty() || path == "-";
}

}  // namespace

void refuseClashes(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    const NamedPath& output = outputs[i];
    if (isStandardOutput(output.path)) {
      for (size_t k = 0; k < i; ++k) {
        if (isStandardOutput(outputs[k].path)) {
          throw UsageError(
              fmt::format("{} and {} would both write to standard output; give one of them a file",
                          outputs[k].option, output.option));
        }
      }
      continue;
    }
    for (const NamedPath& input : inputs) {
      if (!input.path.empty() && input.path != "-" && sameFile(input.path, output.path)) {
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

void refuseMisnamedPictures(const std::string& png, const std::string& svg) {
  for (const auto& [option, path, extension] :
       {std::tuple{"--png", png, ".png"}, std::tuple{"--svg", svg, ".svg"}}) {
    std::string given = std::filesystem::path(path).extension().string();
    for (char& c : given) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (!path.empty() && given != extension) {
      throw UsageError(
          fmt::format("{} {}: the picture's file name must end in {}", option, path, extension));
    }
  }
}

}  // namespace datomsim::frontend
