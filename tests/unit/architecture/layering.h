// The layering law of docs/architecture.md as a check: the table of layers read from the
// document, the includes read from the sources, and every breach named with its file and line.
#pragma once

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace datomsim::testing {

struct Layer {
  std::string library;          // the CMake library, e.g. datomsim_sim
  std::set<std::string> uses;   // as written in the table
  std::set<std::string> never;  // layers it must not reach through any chain of includes
};

// The layers of the table in an architecture document, by name: the rows before the document's
// first section ("## "). Rows look like
// "| `sim` | `datomsim_sim` | what it holds | program, motion | world |"; "-" means none.
std::map<std::string, Layer> readLayerTable(const std::string& markdown);

// A folder outside src/ built on the layers: the command line, the Python module, the benchmarks,
// the fuzzers. It may include the public API, its own headers, the layers it uses (and what they
// use), and the headers of the front ends it uses; nothing by a relative path out of its folder.
struct FrontEnd {
  std::set<std::string> layers;     // of src/, with the layers below them
  std::set<std::string> frontEnds;  // other front ends whose headers it includes
};

// The table of the section "## Front ends" of an architecture document, by folder (relative to
// the repository). Rows look like "| `apps/datomsim` | what it holds | frontend, io |"; a name
// with a slash, or one that is not a layer, is a front end.
std::map<std::string, FrontEnd> readFrontEndTable(const std::string& markdown,
                                                  const std::map<std::string, Layer>& layers);

// Every breach of the law in a source tree (root/<layer>/*.h, *.cpp), one sentence each:
//   - a folder that is not a layer of the table;
//   - an include of a layer that is neither the file's own nor reached by its "uses" column,
//     followed layer to layer;
//   - a file that reaches a layer of its "never" column through any chain of includes.
std::vector<std::string> layeringBreaches(const std::filesystem::path& root,
                                          const std::map<std::string, Layer>& layers);

// Every breach of the front ends' rows in a repository (repository/<front end>/*.h, *.cpp):
//   - a row naming a folder that does not exist;
//   - an include of a layer of src/ that the row does not reach;
//   - an include by a relative path out of the folder ("../");
//   - an include of a header that is neither the folder's own nor a used front end's.
std::vector<std::string> frontEndBreaches(const std::filesystem::path& repository,
                                          const std::map<std::string, Layer>& layers,
                                          const std::map<std::string, FrontEnd>& frontEnds);

// Every breach of the law in the CMake files: a layer's library (src/<layer>/CMakeLists.txt) or a
// front end's targets (<front end>/CMakeLists.txt) linking the library of a layer they do not
// use, directly or through the layers they use.
std::vector<std::string> linkBreaches(const std::filesystem::path& repository,
                                      const std::map<std::string, Layer>& layers,
                                      const std::map<std::string, FrontEnd>& frontEnds);

// The quoted includes of a file, with their line numbers.
struct Include {
  std::string path;  // as written between the quotes
  int line;
};
std::vector<Include> includesOf(const std::filesystem::path& file);

// Each layer and every layer below it, through the "uses" column.
std::map<std::string, std::set<std::string>> layerClosures(
    const std::map<std::string, Layer>& layers);

}  // namespace datomsim::testing
