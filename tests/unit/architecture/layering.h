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
  std::set<std::string> uses;   // as written in the table
  std::set<std::string> never;  // layers it must not reach through any chain of includes
};

// The layers of the table in an architecture document, by name. Rows look like
// "| `sim` | `datomsim_sim` | what it holds | program, motion | world |"; "-" means none.
std::map<std::string, Layer> readLayerTable(const std::string& markdown);

// Every breach of the law in a source tree (root/<layer>/*.h, *.cpp), one sentence each:
//   - a folder that is not a layer of the table;
//   - an include of a layer that is neither the file's own nor reached by its "uses" column,
//     followed layer to layer;
//   - a file that reaches a layer of its "never" column through any chain of includes.
std::vector<std::string> layeringBreaches(const std::filesystem::path& root,
                                          const std::map<std::string, Layer>& layers);

}  // namespace datomsim::testing
