// Writing a command's outputs whole or not at all: a file appears only once all of it is written
// (or standard output takes it), and outputs that would clash are refused before anything is
// read or written.
#pragma once

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "datomsim/result.h"
#include "frontend/reporter.h"

namespace datomsim::frontend {

// Writes text to a file atomically, or to standard output when the path is empty or "-"; a file
// is reported (Reporter::reportWritten).
void writeOutput(const std::string& path, const std::string& text, const Reporter& reporter);
// The same for text written as it is made, by `write` on an open file.
void writeOutput(const std::string& path, const std::function<Status(std::FILE*)>& write,
                 const Reporter& reporter);

// A file a command reads or writes, with the option that names it ("scene", "--out"). An output
// path that is empty or "-" is standard output.
struct NamedPath {
  std::string option;
  std::string path;
};

// Refuses, before anything is read or written, outputs that would overwrite an input, two
// outputs naming the same file, and two outputs both on standard output.
void refuseClashes(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

// Refuses a picture whose file name does not end as its format (--png in .png, --svg in .svg, any
// case): a file named otherwise would hold what its name does not say. Empty paths are not asked.
void refuseMisnamedPictures(const std::string& png, const std::string& svg);

}  // namespace datomsim::frontend
