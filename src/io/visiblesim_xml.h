// VisibleSim's XML scene format: the subset this project reads and writes
// (docs/conventions.md, section 6; docs/file-formats.md).
//
//   <world gridSize="X,Y,Z"> <camera .../> <spotlight .../>
//     <blockList blockSize="10,10,10" color="r,g,b">
//       <block position="x,y,z" color="r,g,b" orientation="o"/> ...
//     <targetList> <target format="grid|csg"> ... (docs/file-formats.md, "Targets")
//
// Blocks carry no id: they get 1, 2, 3... in file order (the paper's mobile, listed first, is 1),
// unless a block has an id attribute. Unknown elements and attributes are ignored. Every error
// names the source, the line, the attribute and its value, e.g.
//   scene.xml:4: block position "1,2" must be three integers x,y,z
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

#include "datomsim/result.h"
#include "io/scene.h"

namespace datomsim::io {

// Reads a scene from XML text; `source` names it in errors (usually the file's path). Latches all
// neighbours of the loaded world.
Result<Scene> parseVisibleSimXml(std::string_view text, std::string_view source);

// The scene as XML. Deterministic: the same scene gives the same bytes. Block ids are written
// only when they are not 1, 2, 3... in order. Refuses viewer attribute names that are not XML
// names.
Result<std::string> toVisibleSimXml(const Scene& scene);

// Streams the XML to an open file, for large scenes.
Status writeVisibleSimXml(const Scene& scene, std::FILE* file);

}  // namespace datomsim::io
