// A command's files, in one place: every input it reads and every output it writes are checked
// together before anything is read or written (docs/limits.md, "Files"), and the outputs are
// written whole at the end, all of them or none.
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "datomsim/result.h"
#include "frontend/reporter.h"

namespace datomsim::frontend {

// A file a command reads or writes, with the option that names it ("scene", "--out"). An output
// path that is empty or "-" is standard output.
struct NamedPath {
  std::string option;
  std::string path;
};

// The outputs of one command, checked against each other and against every input when made:
// - no output is an input (the same file, through any symlink or hard link), no two outputs name
//   one file, and at most one output is standard output;
// - an output that is a directory, in a directory that is missing or not writable, or a special
//   file other than a character device or a FIFO, is refused; a FIFO no process reads is
//   refused rather than waited for;
// - a regular file (or a new one) is written to a hidden partial file beside it, made now, and
//   renamed onto it by commit(); a symlink is followed, so that its target is replaced and the
//   link stays; a character device (/dev/null, a terminal) or a FIFO is opened now and written
//   into at commit, never replaced.
// Until commit() the outputs are held (partial files, memory); a CommandFiles destroyed without
// commit() (the command failed) removes its partial files and the directories it made, and
// leaves every existing file as it was.
class CommandFiles {
 public:
  // Throws UsageError naming the option and the path. `directory`, when not empty, is made
  // (with its missing parents) for outputs inside it, and removed again if the command fails;
  // `directoryOption` names it in messages.
  CommandFiles(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs,
               const std::filesystem::path& directory = {},
               const std::string& directoryOption = {});
  ~CommandFiles();
  CommandFiles(const CommandFiles&) = delete;
  CommandFiles& operator=(const CommandFiles&) = delete;

  // The content of the output `name`, its option (when no other output has it) or its path:
  // written as it is made by `write`, or as text. Throws UsageError (or CheckFailed with write's
  // error) when it cannot be written.
  void write(const std::string& name, const std::function<Status(std::FILE*)>& write);
  void write(const std::string& name, std::string_view text);
  // What the "wrote FILE (...)" line says the output holds.
  void describe(const std::string& name, std::string holds);

  // Puts every output written in place: partial files renamed onto their files, streams
  // written; each file reported (Reporter::reportWritten).
  void commit(const Reporter& reporter);

  struct Output;  // one output's state (output_file.cpp)

 private:
  Output& find(const std::string& name);
  // Makes `directory` and its missing parents, kept in madeDirectories_.
  void makeDirectory(const std::filesystem::path& directory, const std::string& option);
  // Removes the partial files and the directories made.
  void undo();
  std::vector<std::unique_ptr<Output>> outputs_;
  std::vector<Output*> written_;  // in the order written, which commit() keeps
  std::vector<std::filesystem::path> madeDirectories_;  // outermost first
  bool committed_ = false;
};

// The first check CommandFiles makes, for a command whose output is written by another program
// (a video, by ffmpeg): no output is an input, no two outputs name one file, at most one output
// is standard output.
void refuseClashes(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

// Refuses a picture whose file name does not end as its format (--png in .png, --svg in .svg, any
// case): a file named otherwise would hold what its name does not say. Empty paths are not asked.
void refuseMisnamedPictures(const std::string& png, const std::string& svg);

}  // namespace datomsim::frontend
