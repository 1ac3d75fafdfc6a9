// The project's own scene format: versioned JSON, documented in docs/file-formats.md.
//
//   {"format": "datomsim-scene", "version": 1, "grid": [X,Y,Z] or null, "blockSize": [10,10,10],
//    "modules": [{"id":1,"cell":[x,y,z],"orientation":o,"color":[r,g,b]}, ...],
//    "targets": [{"format":"grid","cells":[[x,y,z], ...]}, {"format":"csg","content":"..."}]}
//
// Built for millions of modules: the writer streams the modules array one module per line, and the
// reader is a SAX handler that never holds the document as a tree. Output is deterministic (the
// same scene gives the same bytes). Errors name the source and either a line:column (syntax) or a
// JSON path (meaning), e.g. "box.json: modules[3].cell: expected three integers, got [1,2]".
#pragma once

#include <cstdio>
#include <istream>
#include <string>
#include <string_view>

#include "datomsim/result.h"
#include "io/scene.h"

namespace datomsim::io {

inline constexpr std::string_view kJsonSceneFormat = "datomsim-scene";
inline constexpr int kJsonSceneVersion = 1;

// Reads a scene from JSON text; `source` names it in errors. Latches all neighbours.
Result<Scene> parseJsonScene(std::string_view text, std::string_view source);

// Reads a scene from a stream without loading the whole text. A syntax error rereads the stream
// from its start to turn the byte offset into a line and column, so it must be seekable.
Result<Scene> parseJsonScene(std::istream& input, std::string_view source);

// The scene as JSON text.
std::string toJson(const Scene& scene);

// Streams the JSON to an open file; the error is the system's when a write fails.
Status writeJson(const Scene& scene, std::FILE* file);

}  // namespace datomsim::io
